// gpsurf.Mesh and what makes or transforms one: read, sample, infer, subdivide, edit, simplify.
#include <pybind11/stl.h>

#include <cmath>
#include <optional>

#include "core/io/json_text.h"
#include "core/io/mesh_io.h"
#include "core/mesh/covariance_mesh.h"
#include "core/support/error.h"
#include "core/mesh/inference.h"
#include "core/mesh/mesh_connectivity.h"
#include "core/modelling/samples.h"
#include "core/mesh/sharpness.h"
#include "core/fitting/limit_placement.h"
#include "core/fitting/mesh_simplification.h"
#include "core/modelling/operation_list.h"
#include "core/plans/planned_surface.h"
#include "core/reference/reference_subdivision.h"
#include "python/arrays.h"
#include "python/background_call.h"
#include "python/bindings.h"
#include "python/handles.h"

namespace gps::python {
namespace {

using Crease = std::tuple<int, int, double>;

std::vector<Vec3> means_of(const CovarianceMesh& m) {
  std::vector<Vec3> means(m.n_vertices());
  for (size_t i = 0; i < means.size(); ++i) means[i] = m.mean(i);
  return means;
}

// A mesh from arrays; covariances inferred (GPS paper Eq. 16-17, bias 0.05) when not given.
MeshHandle make_mesh(const py::object& positions, const py::object& faces, const py::object& covariances) {
  std::vector<Vec3> means = array_to_rows(positions, "positions");
  std::vector<Mat3> sigmas;
  const bool infer = covariances.is_none();
  if (!infer) {
    sigmas = array_to_matrices(covariances, "covariances");
    if (sigmas.size() != means.size())
      throw py::value_error("covariances: " + std::to_string(sigmas.size()) + " matrices for " +
                            std::to_string(means.size()) + " positions");
  }
  PolygonTopology topology = faces_from(faces);
  return call_in_background(
      [means = std::move(means), sigmas = std::move(sigmas), topology = std::move(topology),
       infer](CallControl&) mutable {
        CovarianceMesh m = make_covariance_mesh(std::move(means), std::move(sigmas), std::move(topology));
        if (infer) infer_covariances(m);
        validate_gaussians(m);
        return hold(std::move(m));
      },
      py::none(), false);
}

// A copy of `mesh` with `edit` applied, if its Gaussians and sharpness are still valid.
template <class Edit>
void replace(MeshHandle& handle, Edit edit) {
  CovarianceMesh edited = *handle.mesh;
  edit(edited);
  validate_gaussians(edited);
  handle.mesh = std::make_shared<const CovarianceMesh>(std::move(edited));
}

Sharpness with_creases(const CovarianceMesh& c, const std::vector<Crease>& creases) {
  Sharpness s = c.sharpness;
  s.creases.clear();
  for (const auto& [a, b, sharpness] : creases) {
    if (const std::string problem = sharpness_problem(sharpness); !problem.empty())
      throw py::value_error("creases: the sharpness of edge " + std::to_string(a) + "-" + std::to_string(b) + " " +
                            problem);
    if (a < 0 || b < 0 || size_t(a) >= c.n_vertices() || size_t(b) >= c.n_vertices())
      throw py::index_error("creases: edge " + std::to_string(a) + "-" + std::to_string(b) +
                            " names a vertex out of range 0.." + std::to_string(c.n_vertices() - 1));
    s.set_crease(a, b, sharpness);
  }
  crease_level(s, c.connectivity(), int(c.n_vertices()));  // throws for a pair that is not an edge
  return s;
}

std::vector<Crease> creases_of(const CovarianceMesh& c) {
  std::vector<Crease> out;
  for (const EdgeCrease& e : c.sharpness.creases) out.emplace_back(e.a, e.b, e.sharpness);
  return out;
}

std::vector<double> corners_from(const CovarianceMesh& c, const DoubleArray& corners) {
  if (corners.ndim() != 1 || (corners.size() != 0 && size_t(corners.size()) != c.n_vertices()))
    throw py::value_error("corners: expected " + std::to_string(c.n_vertices()) + " values or none");
  std::vector<double> values(corners.data(), corners.data() + corners.size());
  for (size_t v = 0; v < values.size(); ++v)
    if (const std::string problem = sharpness_problem(values[v]); !problem.empty())
      throw py::value_error("corners: vertex " + std::to_string(v) + "'s sharpness " + problem);
  return values;
}

// What a pickled Mesh holds: positions, faces (offsets and indices), covariances, creases, corners.
py::tuple state_of(const MeshHandle& h) {
  const CovarianceMesh& c = *h.mesh;
  const PolygonTopology& t = c.topology();
  return py::make_tuple(rows_to_array(means_of(c)), int_array(t.offsets), int_array(t.verts),
                        matrices_to_array(c.covariances), creases_of(c), double_array(c.sharpness.corners));
}

// The mesh of a pickled state of 6 items (from_state).
MeshHandle mesh_of_state(const py::tuple& state) {
  PolygonTopology t;
  t.offsets = state[1].cast<std::vector<int>>();
  t.verts = state[2].cast<std::vector<int>>();
  if (t.offsets.empty() || t.offsets.front() != 0 || size_t(t.offsets.back()) != t.verts.size())
    throw py::value_error("Mesh: the pickled face offsets do not match the indices");
  for (size_t f = 1; f < t.offsets.size(); ++f)
    if (t.offsets[f] < t.offsets[f - 1]) throw py::value_error("Mesh: the pickled face offsets decrease");
  CovarianceMesh m = make_covariance_mesh(array_to_rows(state[0], "positions"),
                                          array_to_matrices(state[3], "covariances"), std::move(t), "pickled mesh");
  validate_gaussians(m, "pickled mesh");
  m.sharpness = with_creases(m, state[4].cast<std::vector<Crease>>());
  m.sharpness.corners = corners_from(m, state[5].cast<DoubleArray>());
  m.sharpness.normalise();
  return hold(std::move(m));
}

MeshHandle from_state(const py::tuple& state) {
  if (state.size() != 6) throw py::value_error("Mesh: a pickled state of 6 items expected");
  try {
    return mesh_of_state(state);
  } catch (const py::cast_error&) {
    throw py::type_error(
        "Mesh: a pickled state holds positions, face offsets, face indices, covariances, creases "
        "and corners; an item is not of its type");
  }
}

// A str as UTF-8; a ValueError naming `where` for one with a lone surrogate (from os.listdir, or a
// "\ud800" escape), which is not text.
std::string text_of(const py::handle& text, const std::string& where) {
  Py_ssize_t size = 0;
  const char* data = PyUnicode_AsUTF8AndSize(text.ptr(), &size);
  if (!data) {
    PyErr_Clear();
    throw py::value_error(where + " holds a lone surrogate, which is not text");
  }
  return std::string(data, size_t(size));
}

// `value` as json.dumps takes it: numpy's scalars and arrays as Python numbers and lists, in dicts and
// sequences too. A number that is not finite, which JSON cannot hold, or a str that is not text is a
// ValueError naming `where`; so is nesting deeper than the command line's JSON reader takes (a dict
// or list that holds itself among them), walked here before the stack would overflow.
py::object json_ready(const py::handle& value, const std::string& where, int depth = 0) {
  static const py::handle numpy_scalar = py::object(py::module_::import("numpy").attr("generic")).release();
  if (size_t(depth) > kMaxJsonDepth)
    throw py::value_error(where + " is nested more than " + std::to_string(kMaxJsonDepth) +
                          " levels deep (or holds itself)");
  if (py::isinstance<py::array>(value) || py::isinstance(value, numpy_scalar))
    return json_ready(value.attr("tolist")(), where, depth + 1);
  if (PyFloat_Check(value.ptr()) && !std::isfinite(PyFloat_AsDouble(value.ptr())))
    throw py::value_error(where + " is not finite");
  if (py::isinstance<py::str>(value)) text_of(value, where);
  if (py::isinstance<py::dict>(value)) {
    py::dict out;
    for (const auto& [key, item] : value.cast<py::dict>()) out[key] = json_ready(item, where, depth + 1);
    return out;
  }
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    py::list out;
    for (const py::handle item : value) out.append(json_ready(item, where, depth + 1));
    return out;
  }
  return py::reinterpret_borrow<py::object>(value);
}

// The JSON text of edit's `ops`: a str as it is, or a list of dicts as Python writes it, each number
// that is not finite named by its op and key.
std::string ops_text(const py::object& ops) {
  if (py::isinstance<py::str>(ops)) return text_of(ops, "ops");
  const py::object dumps = py::module_::import("json").attr("dumps");
  if (!py::isinstance<py::list>(ops) && !py::isinstance<py::tuple>(ops))
    return dumps(json_ready(ops, "ops")).cast<std::string>();
  py::list list;
  for (const py::handle item : ops) {
    std::string where = "ops[" + std::to_string(list.size()) + "]";
    if (!py::isinstance<py::dict>(item)) {
      list.append(json_ready(item, where));
      continue;
    }
    const py::dict op = item.cast<py::dict>();
    if (op.contains("op") && py::isinstance<py::str>(op["op"]))
      where += " (" + text_of(op["op"], where + ": \"op\"") + ")";
    py::dict fields;
    for (const auto& [key, value] : op) fields[key] = json_ready(value, where + ": " + dumps(key).cast<std::string>());
    list.append(fields);
  }
  return dumps(list).cast<std::string>();
}

std::string describe(const MeshHandle& h) {
  const CovarianceMesh& c = *h.mesh;
  std::string text =
      "<gpsurf.Mesh: " + std::to_string(c.n_vertices()) + " vertices, " + std::to_string(c.n_faces()) + " faces";
  if (!c.sharpness.creases.empty()) text += ", " + std::to_string(c.sharpness.creases.size()) + " creases";
  return text + ">";
}

}  // namespace

void add_mesh_bindings(py::module_& m) {
  py::class_<MeshHandle>(m, "Mesh",
                         "A covariance mesh: a polygon mesh whose every vertex carries a 3D Gaussian.\n\n"
                         "Its arrays are read-only copies: assign a whole array (mesh.positions = p) to change them, "
                         "which checks it and replaces the mesh's state; a Surface made from the mesh is then brought "
                         "up to date by surface.update(mesh).")
      .def(py::init(&make_mesh), py::arg("positions"), py::arg("faces"), py::arg("covariances") = py::none(),

           "positions: (n, 3) float array; faces: (m, k) integer array, or a sequence of vertex index sequences for "
           "faces of several sizes (counted from 0); covariances: (n, 3, 3) symmetric positive definite matrices, "
           "inferred from the faces (GPS paper Eq. 16-17, bias 0.05) when None. Raises ValueError for a wrong shape "
           "or a position that is not finite or lies beyond ±1e100, gpsurf.Error for faces or Gaussians the mesh "
           "cannot have.")
      // Read by the package's __init__, which refuses a second call: pybind11 would ignore it.
      .def_property_readonly("_initialised", [](const MeshHandle& h) { return initialised(h); })
      .def_property_readonly(
          "n_vertices", [](const MeshHandle& h) { return h.mesh->n_vertices(); }, "the number of vertices")
      .def_property_readonly(
          "n_faces", [](const MeshHandle& h) { return h.mesh->n_faces(); }, "the number of faces")
      .def_property(
          "positions", [](const MeshHandle& h) { return read_only(rows_to_array(means_of(*h.mesh))); },
          [](MeshHandle& h, const py::object& a) {
            const auto rows = array_to_rows(a, "positions");
            if (rows.size() != h.mesh->n_vertices())
              throw py::value_error("positions: expected " + std::to_string(h.mesh->n_vertices()) + " rows, got " +
                                    std::to_string(rows.size()));
            replace(h, [&](CovarianceMesh& c) {
              for (size_t i = 0; i < rows.size(); ++i) c.set_mean(i, rows[i]);
            });
          },
          "the means, an (n, 3) read-only array; assign an (n, 3) array to change them")
      .def_property(
          "covariances", [](const MeshHandle& h) { return read_only(matrices_to_array(h.mesh->covariances)); },
          [](MeshHandle& h, const py::object& a) {
            auto matrices = array_to_matrices(a, "covariances");
            if (matrices.size() != h.mesh->n_vertices())
              throw py::value_error("covariances: expected " + std::to_string(h.mesh->n_vertices()) +
                                    " matrices, got " + std::to_string(matrices.size()));
            replace(h, [&](CovarianceMesh& c) { c.covariances = std::move(matrices); });
          },
          "the covariances, an (n, 3, 3) read-only array; assign an (n, 3, 3) array to change them")
      .def_property_readonly(
          "faces", [](const MeshHandle& h) { return read_only(faces_to_array(h.mesh->topology())); },
          "the faces as an (m, k) read-only int32 array of vertex indices (from 0); ValueError for a mesh with faces "
          "of several sizes, whose faces are face_offsets and face_indices")
      .def_property_readonly(
          "face_offsets", [](const MeshHandle& h) { return read_only(int_array(h.mesh->topology().offsets)); },
          "face f's vertices are face_indices[face_offsets[f]:face_offsets[f + 1]] (m + 1 offsets, read-only)")
      .def_property_readonly(
          "face_indices", [](const MeshHandle& h) { return read_only(int_array(h.mesh->topology().verts)); },
          "every face's vertex indices, one face after another (read-only int32)")
      .def_property(
          "creases", [](const MeshHandle& h) { return py::tuple(py::cast(creases_of(*h.mesh))); },
          [](MeshHandle& h, const py::object& triples) {
            std::vector<Crease> creases;
            try {
              creases = triples.cast<std::vector<Crease>>();
            } catch (const py::cast_error&) {
              throw py::type_error(
                  "creases: expected a sequence of (a, b, sharpness) triples: an edge's two vertex indices and "
                  "its sharpness");
            }
            Sharpness s = with_creases(*h.mesh, creases);
            replace(h, [&](CovarianceMesh& c) { c.sharpness = std::move(s); });
          },
          "the creased edges, a tuple of (a, b, sharpness) with a < b: 0 smooth, 10 and above infinitely sharp "
          "(OpenSubdiv's semi-sharp creases); assign a sequence of such triples to set them all")
      .def_property_readonly(
          "crease_edges",
          [](const MeshHandle& h) {
            const auto& creases = h.mesh->sharpness.creases;
            IntArray a({py::ssize_t(creases.size()), py::ssize_t(2)});
            for (size_t i = 0; i < creases.size(); ++i) {
              a.mutable_data()[2 * i] = creases[i].a;
              a.mutable_data()[2 * i + 1] = creases[i].b;
            }
            return read_only(a);
          },
          "the creased edges as a (c, 2) read-only int32 array, in the order of creases")
      .def_property_readonly(
          "crease_sharpness",
          [](const MeshHandle& h) {
            std::vector<double> s;
            for (const EdgeCrease& e : h.mesh->sharpness.creases) s.push_back(e.sharpness);
            return read_only(double_array(s));
          },
          "the creased edges' sharpness, a (c,) read-only array")
      .def_property(
          "corners", [](const MeshHandle& h) { return read_only(double_array(h.mesh->sharpness.corners)); },
          [](MeshHandle& h, const DoubleArray& corners) {
            std::vector<double> values = corners_from(*h.mesh, corners);
            replace(h, [&](CovarianceMesh& c) {
              c.sharpness.corners = std::move(values);
              c.sharpness.normalise();
            });
          },
          "the corner sharpness of every vertex, an (n,) read-only array (empty where no vertex is sharp); assign n "
          "values (or none) to set them")
      .def(
          "write",
          [](const MeshHandle& h, const py::object& path, bool binary) {
            const std::string file = path_of(path);
            const std::shared_ptr<const CovarianceMesh> mesh = h.mesh;
            without_gil([&] { write_mesh(file, *mesh, binary); });
          },
          py::arg("path"), py::arg("binary") = false,
          "Writes the mesh (atomically) to a str or os.PathLike path: .ply keeps the "
          "covariances, creases and corners exactly (binary: little-endian), .obj positions, faces and creases")
      .def(
          "copy", [](const MeshHandle& h) { return MeshHandle{h.mesh}; },
          "A copy of the mesh (assigning to either leaves the other)")
      .def("__copy__", [](const MeshHandle& h) { return MeshHandle{h.mesh}; })
      .def(
          "__deepcopy__", [](const MeshHandle& h, const py::object&) { return MeshHandle{h.mesh}; }, py::arg("memo"))
      .def("__repr__", &describe)
      .def("__getstate__", &state_of)
      // The state of a tuple of 6 items replaces the mesh; anything else is refused. Named
      // __setstate__ below: pybind11 takes a method of that name for a constructor, which an instance
      // made already skips, ignoring what it was given.
      .def("_set_state",
           [](MeshHandle& h, const py::object& state) {
             if (!py::isinstance<py::tuple>(state))
               throw py::type_error("Mesh: a pickled state is a tuple of 6 items, not " +
                                    std::string(py::str(py::type::of(state).attr("__name__"))));
             h.mesh = from_state(state.cast<py::tuple>()).mesh;
           })
      // Every pickle protocol rebuilds the mesh through _mesh_from_state: protocols 0 and 1 would
      // otherwise make the instance with object.__new__, which a compiled class refuses.
      .def("__reduce__", [](const MeshHandle& h) {
        return py::make_tuple(py::module_::import("gpsurf").attr("_mesh_from_state"), py::make_tuple(state_of(h)));
      });
  m.attr("Mesh").attr("__setstate__") = m.attr("Mesh").attr("_set_state");
  m.def("_mesh_from_state", &from_state, py::arg("state"), "A Mesh from its pickled state (gpsurf._mesh_from_state)");

  m.def(
      "read",
      [](const py::object& path, const std::string& covariance, double bias, double isotropic, bool repair) {
        ImportOptions o;
        if (covariance != "infer" && covariance != "isotropic")
          throw py::value_error("covariance: expected 'infer' or 'isotropic', got '" + covariance + "'");
        o.covariance = covariance == "infer" ? ImportOptions::Covariance::infer : ImportOptions::Covariance::isotropic;
        o.bias = positive_number(bias, "bias");
        o.isotropic_scale = positive_number(isotropic, "isotropic");
        o.repair = repair;
        return call_in_background([file = path_of(path), o](CallControl&) { return hold(read_mesh(file, o)); },
                                  py::none(), false);
      },
      py::arg("path"), py::arg("covariance") = "infer", py::arg("bias") = 0.05, py::arg("isotropic") = 0.5,
      py::arg("repair") = false,

      "Reads a covariance PLY, or a plain PLY/OBJ/OFF/STL with covariances inferred (covariance='infer', GPS paper "
      "Eq. 16-17 with `bias`) or isotropic (sigma = `isotropic` x the mean edge length at the vertex). repair: weld, "
      "split pinches and fins, drop degenerate faces and orient, as gpsurf --repair. path: str or os.PathLike. "
      "Raises gpsurf.Error naming the file and line.");
  m.def(
      "edit",
      [](const MeshHandle& mesh, const py::object& ops) {
        return call_in_background(
            [text = ops_text(ops), source = mesh.mesh](CallControl&) {
              return hold(OperationList::parse(text, std::string()).apply(*source).mesh);  // named ops[i]
            },
            py::none(), false);
      },
      py::arg("mesh"), py::arg("ops"),
      "A copy of the mesh changed by modelling operations, as gpsurf edit --ops takes them: a list "
      "such as [{'op': 'loop_cut', 'edge': [0, 1]}, {'op': 'extrude', 'faces': [4], 'distance': 0.5}] (or its JSON "
      "text); numpy's numbers and arrays in it count as Python's. Raises gpsurf.Error naming the operation (ops[i]) "
      "and what is wrong, ValueError for a number that is not finite.");
  m.def(
      "simplify",
      [](const MeshHandle& mesh, std::optional<Integer> vertices, double bias, const py::object& progress,
         std::optional<double> error, bool quads, bool limit) {
        if (!vertices && !error) throw py::value_error("simplify: give vertices=N or error=E");
        SimplifyOptions o;
        // error alone: as few vertices as the error allows, as gpsurf simplify --error does.
        o.target_vertices = 4;
        if (vertices) {
          const long long count = clamped(*vertices);
          if (count < 4) throw py::value_error("vertices: expected at least 4, got " + shown_integer(*vertices));
          o.target_vertices = size_t(count);
        }
        o.bias = positive_number(bias, "bias");
        if (error && !(*error > 0 && *error <= 1))
          throw py::value_error("error: expected a number above 0 and at most 1, got " + shown_number(*error));
        o.max_error = error.value_or(0);
        o.quads = quads;
        return call_in_background(
            [o, limit, source = mesh.mesh](CallControl& control) mutable {
              o.progress = control.progress_report();
              SimplifiedMesh simplified = simplify_mesh(*source, o);
              if (limit) simplified.mesh = place_for_limit(simplified.mesh, PlanOptions{}).mesh;
              return hold(std::move(simplified.mesh));
            },
            progress, true);
      },
      py::arg("mesh"), py::arg("vertices") = py::none(), py::arg("bias") = 0.05, py::arg("progress") = py::none(),
      py::kw_only(), py::arg("error") = py::none(), py::arg("quads") = false, py::arg("limit") = false,

      "A coarse copy of a triangle mesh with about `vertices` vertices (edge collapses that keep its topology), each "
      "vertex's Gaussian from the input faces collapsed into it (`bias`: their thickness across their planes), as "
      "gpsurf simplify makes it. error: stop short of a collapse that would move the surface further than this "
      "fraction (0 to 1) of the input's bounding-box diagonal (with vertices=None: as few vertices as it allows). "
      "quads: pair the result's triangles into quads where they make nearly square, flat ones. limit: move each "
      "vertex out by how far its limit position falls short of it, so that the limit surface does not look shrunk. "
      "progress: called "
      "with the fraction done (0 to 1); returning False cancels (gpsurf.Cancelled).");
  m.def("samples", &sample_names, "The names of the built-in meshes");
  m.def("sample_description", &sample_description, py::arg("name"),
        "What the built-in mesh `name` is ('' for an unknown name)");
  m.def(
      "sample",
      [](const std::string& name, const Integer& size) {
        return call_in_background(
            [name, faces = to_int(size, "size")](CallControl&) { return hold(make_sample(name, faces)); }, py::none(),
            false);
      },
      py::arg("name"), py::arg("size") = 0,
      "A built-in mesh (samples() names them). size: the face count of grid, sphere and "
      "icosphere (1..4000000), 0 for their default");
  m.def(
      "infer",
      [](const MeshHandle& mesh, double bias) {
        positive_number(bias, "bias");
        return call_in_background(
            [bias, source = mesh.mesh](CallControl&) {
              CovarianceMesh out = *source;
              infer_covariances(out, bias);
              validate_gaussians(out);
              return hold(std::move(out));
            },
            py::none(), false);
      },
      py::arg("mesh"), py::arg("bias") = 0.05,
      "A copy of the mesh with covariances inferred from its faces (GPS paper Eq. 16-17): "
      "per face the second moment of its vertices plus bias x its largest eigenvalue, per vertex the product of its "
      "faces' Gaussians. bias: a finite number above 0.");
  m.def(
      "subdivide",
      [](const MeshHandle& mesh, const Integer& level_count, bool limit, const std::string& scheme,
         const std::string& loop_beta) {
        const int levels = int_in(level_count, 0, 8, "levels");
        const PlanOptions named = plan_options_named(scheme, loop_beta);
        return call_in_background(
            [=, source = mesh.mesh](CallControl&) {
              SubdivisionOptions o;
              o.scheme = scheme_for(source->topology(), named);
              o.levels = levels;
              o.limit = limit;
              o.loop_beta = named.loop_beta;
              return hold(subdivide(*source, o).mesh);
            },
            py::none(), false);
      },
      py::arg("mesh"), py::arg("levels") = 1, py::arg("limit") = true, py::arg("scheme") = "auto",
      py::arg("loop_beta") = "loop",

      "The exact CPU reference: GPS subdivision in 9D, `levels` (0..8) times, then (limit=True) every vertex at its "
      "exact limit. scheme: 'auto' (Loop for a mesh of triangles, else Catmull-Clark), 'loop' or 'catmull-clark'; "
      "loop_beta: 'loop' or 'warren'.");
}

}  // namespace gps::python
