#include "core/evaluation/triangle_mesh.h"

#include <charconv>
#include <sstream>

#include <Eigen/Geometry>

#include "core/io/atomic_file.h"
#include "core/io/gltf_io.h"
#include "core/support/error.h"
#include "core/io/mesh_io.h"
#include "core/support/quoted_text.h"

namespace gps {

namespace {

void write_number(std::ostream& out, double x) {
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, x);
  out.write(buffer, r.ptr - buffer);
}

void write_ply(std::ostream& out, const TriangleMesh& m, bool binary) {
  out << "ply\nformat " << (binary ? "binary_little_endian" : "ascii")
      << " 1.0\ncomment gpsurf tessellated limit surface\n"
      << "element vertex " << m.positions.size() << "\n";
  for (const char* name : {"x", "y", "z", "nx", "ny", "nz"}) out << "property double " << name << "\n";
  out << "element face " << m.triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (size_t i = 0; i < m.positions.size(); ++i) {
    const double v[6] = {m.positions[i].x(), m.positions[i].y(), m.positions[i].z(),
                         m.normals[i].x(),   m.normals[i].y(),   m.normals[i].z()};
    if (binary) {
      out.write(reinterpret_cast<const char*>(v), sizeof v);
      continue;
    }
    for (int k = 0; k < 6; ++k) {
      write_number(out, v[k]);
      out.put(k == 5 ? '\n' : ' ');
    }
  }
  for (const auto& t : m.triangles) {
    if (binary) {
      out.put(char(3));
      out.write(reinterpret_cast<const char*>(t.data()), 12);
    } else {
      out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    }
  }
}

void write_obj(std::ostream& out, const TriangleMesh& m) {
  for (const char* tag : {"v ", "vn "}) {
    const auto& values = tag[1] == 'n' ? m.normals : m.positions;
    for (const Vec3& p : values) {
      out << tag;
      write_number(out, p.x());
      out.put(' ');
      write_number(out, p.y());
      out.put(' ');
      write_number(out, p.z());
      out.put('\n');
    }
  }
  for (const auto& t : m.triangles)
    out << "f " << t[0] + 1 << "//" << t[0] + 1 << ' ' << t[1] + 1 << "//" << t[1] + 1 << ' ' << t[2] + 1 << "//"
        << t[2] + 1 << '\n';
}

// glTF: its positions and normals as they are (normals of the limit surface), without covariances.
void write_gltf_triangles(const std::string& path, const TriangleMesh& m, bool binary) {
  GltfTriangles triangles{m.positions, m.normals, {}, m.triangles};
  for (Vec3& n : triangles.normals) n.normalize();
  std::ostringstream gltf;
  try {
    write_gltf(gltf, triangles, binary);
  } catch (const Error& e) {
    throw Error(escaped(path) + ": " + e.what(), e.kind());
  }
  write_file_atomically(
      path, [&](std::ostream& out) { out << gltf.view(); }, true);
}

}  // namespace

void fill_missing_normals(TriangleMesh& mesh) {
  std::vector<Vec3> around(mesh.positions.size(), Vec3::Zero()), largest(mesh.positions.size(), Vec3::Zero());
  std::vector<char> in_triangle(mesh.positions.size(), 0);
  for (const auto& t : mesh.triangles) {
    const Vec3& a = mesh.positions[size_t(t[0])];
    const Vec3 normal = (mesh.positions[size_t(t[1])] - a).cross(mesh.positions[size_t(t[2])] - a);  // twice the area
    for (const int i : t) {
      around[size_t(i)] += normal;
      in_triangle[size_t(i)] = 1;
      if (normal.squaredNorm() > largest[size_t(i)].squaredNorm()) largest[size_t(i)] = normal;
    }
  }
  // Where the triangles' normals cancel (two sheets back to back), the largest triangle's; where every
  // triangle is degenerate too, any unit normal: a file's normals are unit vectors.
  for (size_t i = 0; i < mesh.normals.size(); ++i) {
    if (!mesh.normals[i].isZero(0.0) || !in_triangle[i]) continue;
    const Vec3& n = !around[i].isZero(0.0) ? around[i] : largest[i];
    mesh.normals[i] = n.isZero(0.0) ? Vec3::UnitZ() : n.normalized();
  }
}

void write_triangle_mesh(const std::string& path, const TriangleMesh& mesh, bool binary) {
  const std::string ext = extension_of(path);
  for (size_t i = 0; i < mesh.positions.size(); ++i)
    if (const std::string why = position_problem(mesh.positions[i]);
        !why.empty() || (i < mesh.normals.size() && !mesh.normals[i].allFinite()))
      throw Error(escaped(path) + ": not written: vertex " + std::to_string(i) + " " +
                  (why.empty() ? "has a normal that is not finite" : why));
  if (ext == ".ply")
    write_file_atomically(
        path, [&](std::ostream& out) { write_ply(out, mesh, binary); }, binary);
  else if (ext == ".obj")
    write_file_atomically(path, [&](std::ostream& out) { write_obj(out, mesh); });
  else if (ext == ".gltf" || ext == ".glb")
    write_gltf_triangles(path, mesh, ext == ".glb");
  else
    throw usage_error(escaped(path) + ": cannot write format " + quoted_token(ext) + " (use .ply, .obj, .gltf or .glb)");
}

}  // namespace gps
