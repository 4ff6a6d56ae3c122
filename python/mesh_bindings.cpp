// gpsurf.Mesh and what makes or transforms one: read, sample, infer, subdivide, edit.
#include <pybind11/stl.h>

#include "core/io/mesh_io.h"
#include "core/mesh/covariance_mesh.h"
#include "core/mesh/error.h"
#include "core/mesh/inference.h"
#include "core/mesh/mesh_connectivity.h"
#include "core/mesh/samples.h"
#include "core/mesh/sharpness.h"
#include "core/fitting/mesh_simplification.h"
#include "core/modelling/operation_list.h"
#include "core/plans/patch_layout.h"
#include "core/reference/reference_subdivision.h"
#include "python/arrays.h"
#include "python/bindings.h"
#include "core/plans/planned_surface.h"

namespace gps::python {
namespace {

std::vector<std::vector<int>> faces_of(const CovarianceMesh& m) {
  std::vector<std::vector<int>> faces;
  faces.reserve(m.n_faces());
  for (const auto f : m.mesh.faces()) faces.push_back(face_vertices(m.mesh, f));
  return faces;
}

std::vector<Vec3> means_of(const CovarianceMesh& m) {
  std::vector<Vec3> means(m.n_vertices());
  for (size_t i = 0; i < means.size(); ++i) means[i] = m.mean(i);
  return means;
}

// A mesh from arrays; covariances inferred (GPS paper Eq. 16-17, bias 0.05) when not given.
CovarianceMesh make_mesh(const DoubleArray& positions, const std::vector<std::vector<int>>& faces,
                         const std::optional<DoubleArray>& covariances) {
  const std::vector<Vec3> means = array_to_rows(positions, "positions");
  std::vector<Mat3> sigmas(means.size(), Mat3::Identity());
  if (covariances) {
    sigmas = array_to_matrices(*covariances, "covariances");
    if (sigmas.size() != means.size())
      throw py::value_error("covariances: " + std::to_string(sigmas.size()) + " matrices for " +
                            std::to_string(means.size()) + " positions");
  }
  CovarianceMesh m = make_covariance_mesh(means, sigmas, faces);
  if (!covariances) infer_covariances(m);
  validate_gaussians(m);
  return m;
}

}  // namespace

void add_mesh_bindings(py::module_& m) {
  py::class_<CovarianceMesh>(m, "Mesh", "A covariance mesh: a polygon mesh whose every vertex carries a 3D Gaussian")
      .def(py::init(&make_mesh), py::arg("positions"), py::arg("faces"), py::arg("covariances") = py::none(),
           "A mesh from an n x 3 array of positions, a list of faces (vertex index lists, counted from 0) and an "
           "n x 3 x 3 array of covariances (inferred from the faces, GPS paper Eq. 16-17, when not given)")
      .def_property_readonly("n_vertices", &CovarianceMesh::n_vertices)
      .def_property_readonly("n_faces", &CovarianceMesh::n_faces)
      .def_property(
          "positions", [](const CovarianceMesh& c) { return rows_to_array(means_of(c)); },
          [](CovarianceMesh& c, const DoubleArray& a) {
            const auto rows = array_to_rows(a, "positions");
            if (rows.size() != c.n_vertices())
              throw py::value_error("positions: expected " + std::to_string(c.n_vertices()) + " rows");
            CovarianceMesh edited = c;
            for (size_t i = 0; i < rows.size(); ++i) edited.set_mean(i, rows[i]);
            validate_gaussians(edited);
            c = std::move(edited);
          },
          "the means, an n x 3 array (a copy; assign an array to change them)")
      .def_property(
          "covariances", [](const CovarianceMesh& c) { return matrices_to_array(c.covariances); },
          [](CovarianceMesh& c, const DoubleArray& a) {
            auto matrices = array_to_matrices(a, "covariances");
            if (matrices.size() != c.n_vertices())
              throw py::value_error("covariances: expected " + std::to_string(c.n_vertices()) + " matrices");
            CovarianceMesh edited = c;
            edited.covariances = std::move(matrices);
            validate_gaussians(edited);
            c = std::move(edited);
          },
          "the covariances, an n x 3 x 3 array (a copy; assign an array to change them)")
      .def_property_readonly("faces", &faces_of, "the faces as lists of vertex indices (from 0)")
      .def_property(
          "creases",
          [](const CovarianceMesh& c) {
            std::vector<std::tuple<int, int, double>> out;
            for (const EdgeCrease& e : c.sharpness.creases) out.emplace_back(e.a, e.b, e.sharpness);
            return out;
          },
          [](CovarianceMesh& c, const std::vector<std::tuple<int, int, double>>& creases) {
            Sharpness s = c.sharpness;
            s.creases.clear();
            for (const auto& [a, b, sharpness] : creases) {
              if (const std::string problem = sharpness_problem(sharpness); !problem.empty())
                throw py::value_error("creases: the sharpness of edge " + std::to_string(a) + "-" + std::to_string(b) +
                                      " " + problem);
              s.set_crease(a, b, sharpness);
            }
            const PolygonTopology t = topology_of(c.mesh);
            crease_level(s, connectivity_of(t), t.n_vertices);  // throws for a pair that is not an edge
            c.sharpness = std::move(s);
          },
          "the creased edges as (a, b, sharpness) with a < b: 0 smooth, 10 and above infinitely sharp (OpenSubdiv's "
          "semi-sharp creases); assign a list of such tuples to set them all")
      .def_property(
          "corners", [](const CovarianceMesh& c) { return c.sharpness.corners; },
          [](CovarianceMesh& c, const std::vector<double>& corners) {
            if (!corners.empty() && corners.size() != c.n_vertices())
              throw py::value_error("corners: expected " + std::to_string(c.n_vertices()) + " values or none");
            for (size_t v = 0; v < corners.size(); ++v)
              if (const std::string problem = sharpness_problem(corners[v]); !problem.empty())
                throw py::value_error("corners: vertex " + std::to_string(v) + "'s sharpness " + problem);
            c.sharpness.corners = corners;
            c.sharpness.normalise();
          },
          "the corner sharpness of every vertex (an empty list where none is sharp)")
      .def(
          "write", [](const CovarianceMesh& c, const std::string& path, bool binary) { write_mesh(path, c, binary); },
          py::arg("path"), py::arg("binary") = false,
          "Writes the mesh: .ply keeps the covariances exactly, .obj positions and faces only")
      .def("copy", [](const CovarianceMesh& c) { return c; })
      .def("__repr__", [](const CovarianceMesh& c) {
        return "<gpsurf.Mesh: " + std::to_string(c.n_vertices()) + " vertices, " + std::to_string(c.n_faces()) +
               " faces>";
      });

  m.def(
      "read",
      [](const std::string& path, const std::string& covariance, double bias, double isotropic) {
        ImportOptions o;
        if (covariance != "infer" && covariance != "isotropic")
          throw py::value_error("covariance: expected 'infer' or 'isotropic', got '" + covariance + "'");
        o.covariance = covariance == "infer" ? ImportOptions::Covariance::infer : ImportOptions::Covariance::isotropic;
        o.bias = bias;
        o.isotropic_scale = isotropic;
        return read_mesh(path, o);
      },
      py::arg("path"), py::arg("covariance") = "infer", py::arg("bias") = 0.05, py::arg("isotropic") = 0.5,
      "Reads a covariance PLY, or a plain PLY/OBJ/OFF/STL with covariances inferred (or isotropic: sigma = "
      "isotropic x the mean edge length at the vertex)");
  m.def(
      "edit",
      [](const CovarianceMesh& mesh, const py::object& ops) {
        // A list of dicts as Python writes it, or the JSON text gpsurf edit --ops takes.
        const std::string text = py::isinstance<py::str>(ops)
                                     ? ops.cast<std::string>()
                                     : py::module_::import("json").attr("dumps")(ops).cast<std::string>();
        return OperationList::parse(text, "ops").apply(mesh).mesh;
      },
      py::arg("mesh"), py::arg("ops"),
      "A copy of the mesh changed by modelling operations, as gpsurf edit --ops takes them: a list such as "
      "[{'op': 'loop_cut', 'edge': [0, 1]}, {'op': 'extrude', 'faces': [4], 'distance': 0.5}] (or its JSON text)");
  m.def(
      "simplify",
      [](const CovarianceMesh& mesh, size_t vertices, double bias) {
        SimplifyOptions o;
        o.target_vertices = vertices;
        o.bias = bias;
        return simplify_mesh(mesh, o).mesh;
      },
      py::arg("mesh"), py::arg("vertices"), py::arg("bias") = 0.05,
      "A coarse copy of a triangle mesh with about `vertices` vertices (edge collapses that keep its topology), each "
      "vertex's Gaussian from the input faces collapsed into it, as gpsurf simplify makes it");
  m.def("samples", &sample_names, "The names of the built-in meshes");
  m.def("sample_description", &sample_description, py::arg("name"));
  m.def("sample", &make_sample, py::arg("name"), py::arg("size") = 0,
        "A built-in mesh (size: the face count of the sized samples, 0 for their default)");
  m.def(
      "infer",
      [](const CovarianceMesh& mesh, double bias) {
        CovarianceMesh out = mesh;
        infer_covariances(out, bias);
        return out;
      },
      py::arg("mesh"), py::arg("bias") = 0.05,
      "A copy of the mesh with covariances inferred from its faces (GPS paper Eq. 16-17)");
  m.def(
      "subdivide",
      [](const CovarianceMesh& mesh, int levels, bool limit, const std::string& scheme, const std::string& loop_beta) {
        if (levels < 0 || levels > 8) throw py::value_error("levels: expected 0..8, got " + std::to_string(levels));
        const PlanOptions named = plan_options_named(scheme, loop_beta);
        SubdivisionOptions o;
        o.scheme = scheme_for(topology_of(mesh.mesh), named);
        o.levels = levels;
        o.limit = limit;
        o.loop_beta = named.loop_beta;
        return subdivide(mesh, o).mesh;
      },
      py::arg("mesh"), py::arg("levels") = 1, py::arg("limit") = true, py::arg("scheme") = "auto",
      py::arg("loop_beta") = "loop",
      "The exact CPU reference: GPS subdivision in 9D, `levels` times, then (limit=True) every vertex at its exact "
      "limit. scheme: 'auto' (Loop for a mesh of triangles, else Catmull-Clark), 'loop' or 'catmull-clark'");
}

}  // namespace gps::python
