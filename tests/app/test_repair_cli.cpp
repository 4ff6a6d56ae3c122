// --repair and --weld on the commands that read a mesh, the refusals that name the defect and the
// option, and `gpsurf info` listing every problem class of a refused mesh. The meshes are OBJ files
// written here, one per defect class.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "core/io/mesh_io.h"
#include "core/mesh/mesh_connectivity.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

using test::gpsurf;
using test::run_command;

using Faces = std::vector<std::vector<int>>;  // numbered from 0 here, from 1 in the file

void write_obj(const std::string& path, const std::vector<Vec3>& p, const Faces& faces) {
  std::ofstream out(path);
  for (const Vec3& x : p) out << "v " << x.x() << ' ' << x.y() << ' ' << x.z() << '\n';
  for (const auto& face : faces) {
    out << 'f';
    for (const int v : face) out << ' ' << v + 1;
    out << '\n';
  }
}

Vec3 corner(int i) { return Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1); }
const Faces kCube = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
std::vector<Vec3> cube_positions() {
  std::vector<Vec3> p;
  for (int i = 0; i < 8; ++i) p.push_back(corner(i));
  return p;
}

// A tetrahedron with its apex at vertex `apex` (new when −1), its other corners new, oriented outwards.
void add_tetrahedron(std::vector<Vec3>& p, Faces& faces, const Vec3& at, int apex, double side) {
  const int a = apex >= 0 ? apex : int(p.size());
  if (apex < 0) p.push_back(at);
  const int b = int(p.size());
  p.insert(p.end(), {at + side * Vec3(1, 0, 0), at + side * Vec3(0, 1, 0), at + side * Vec3(0, 0, 1)});
  if (side > 0)
    faces.insert(faces.end(), {{a, b + 1, b}, {a, b, b + 2}, {a, b + 2, b + 1}, {b, b + 1, b + 2}});
  else  // mirrored: the other winding faces outwards
    faces.insert(faces.end(), {{a, b, b + 1}, {a, b + 2, b}, {a, b + 1, b + 2}, {b, b + 2, b + 1}});
}

// The mesh as read back: manifold (read_mesh builds it), every directed edge once; its boundary edges.
int boundary_edges(const CovarianceMesh& m) {
  const PolygonTopology& t = m.topology();
  std::map<std::pair<int, int>, int> directed;
  for (int f = 0; f < t.n_faces(); ++f)
    for (int k = 0; k < t.face_size(f); ++k)
      ++directed[{t.verts[size_t(t.offsets[size_t(f)] + k)],
                  t.verts[size_t(t.offsets[size_t(f)] + (k + 1) % t.face_size(f))]}];
  int boundary = 0;
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1);
    boundary += directed.count({edge.second, edge.first}) == 0;
  }
  return boundary;
}

struct Case {
  std::string name;
  std::vector<Vec3> positions;
  Faces faces;
  std::string refusal;        // the refusal after "FILE: " ("" where the mesh loads as it is)
  std::string report;         // the repair report's lines
  size_t vertices, faces_after;
  int boundary;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  {
    Case c{"pinch",
           {},
           {},
           "1 non-manifold (pinch) vertex, vertex 1 (line 1) with 2 fans; --repair splits it",
           "repair: split 1 pinch vertex (1 copy added, one per extra fan)\n",
           8,
           8,
           0};
    add_tetrahedron(c.positions, c.faces, Vec3(0, 0, 0), -1, 1);
    add_tetrahedron(c.positions, c.faces, Vec3(0, 0, 0), 0, -1);
    out.push_back(c);
  }
  {
    Case c{"unwelded", {}, {}, "", "repair: welded 24 coincident vertices into 8\n", 8, 6, 0};
    for (const auto& face : kCube) {
      c.faces.emplace_back();
      for (const int v : face) {
        c.faces.back().push_back(int(c.positions.size()));
        c.positions.push_back(corner(v));
      }
    }
    out.push_back(c);
  }
  {
    Case c{"fin",
           {Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 0, 0), Vec3(-1, 0, 1), Vec3(-1, 0, 0), Vec3(0, 1, 1),
            Vec3(0, 1, 0)},
           {{0, 1, 2, 3}, {0, 1, 6, 7}, {1, 0, 5, 4}},
           "1 non-manifold edge (a fin: more than two faces), the edge of vertex 1 (line 1) and vertex 2 (line 2) "
           "with 3 faces; --repair gives the extra faces their own vertices",
           "repair: separated 1 face from 1 edge with more than two faces (2 vertex copies)\n",
           10,
           3,
           10};
    out.push_back(c);
  }
  {
    Case c{"dangling",
           {},
           {},
           "2 non-manifold (pinch) vertices, the first vertex 2 (line 2) with 2 fans; --repair splits them",
           "repair: split 2 pinch vertices (2 copies added, one per extra fan)\n",
           10,
           6,
           6};
    add_tetrahedron(c.positions, c.faces, Vec3(0, 0, 0), -1, 1);
    c.positions.insert(c.positions.end(), {Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(0, 2, 0), Vec3(1, 2, 0)});
    c.faces.insert(c.faces.end(), {{1, 4, 5}, {2, 6, 7}});
    out.push_back(c);
  }
  {
    Case c{"faces",
           {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(0.5, 0, 0)},
           {{0, 1, 2}, {0, 2, 3}, {2, 0, 1}, {0, 4, 1}, {3, 3, 0}},
           "1 degenerate face (fewer than 3 distinct corners), face 5 (line 10); --repair drops it; 1 duplicate "
           "face (on the vertices of an earlier one), face 3 (line 8) as face 1 (line 6); --repair drops it",
           "repair: dropped 1 degenerate face (fewer than 3 distinct corners)\nrepair: dropped 1 zero-area face\n"
           "repair: dropped 1 duplicate face\nrepair: dropped 1 vertex left in no face\n",
           4,
           2,
           4};
    out.push_back(c);
  }
  {
    Case c{"isolated", cube_positions(), kCube, "", "repair: dropped 2 isolated vertices\n", 8, 6, 0};
    c.positions.push_back(Vec3(5, 5, 5));
    c.positions.push_back(Vec3(-5, 5, 5));
    out.push_back(c);
  }
  {
    Case c{"flipped",
           cube_positions(),
           kCube,
           "1 face oriented against its neighbours, face 4 (line 12); --repair flips it",
           "repair: flipped 1 face to orient each part consistently\n",
           8,
           6,
           0};
    std::reverse(c.faces[3].begin() + 1, c.faces[3].end());
    out.push_back(c);
  }
  {
    // A closed pillow of two triangles on the same vertices (no subdivision can refine it).
    Case c{"pillow",
           {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)},
           {{0, 1, 2}, {0, 2, 1}},
           "1 duplicate face (on the vertices of an earlier one), face 2 (line 5) as face 1 (line 4); --repair "
           "drops it",
           "repair: dropped 1 duplicate face\n",
           3,
           1,
           3};
    out.push_back(c);
  }
  {
    // A bow tie: one face through vertex 1 twice, split into its two triangles, which then pinch there.
    Case c{"bowtie",
           {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(-1, 0, 0), Vec3(-1, -1, 0)},
           {{0, 1, 2, 0, 3, 4}},
           "1 face with a repeated corner, face 1 (line 6); --repair removes the repeat; 1 non-manifold (pinch) "
           "vertex, vertex 1 (line 1) with 2 fans; --repair splits it",
           "repair: removed repeated corners from 1 face (1 split into loops)\nrepair: split 1 pinch vertex (1 copy "
           "added, one per extra fan)\n",
           6,
           2,
           6};
    out.push_back(c);
  }
  {
    // A square of two triangles and a zero-area one along its edge 1–2 through vertex 5: read as it is.
    Case c{"sliver",
           {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(0.5, 0, 0)},
           {{0, 1, 2}, {0, 2, 3}, {0, 4, 1}},
           "",
           "repair: dropped 1 zero-area face\nrepair: dropped 1 vertex left in no face\n",
           4,
           2,
           4};
    out.push_back(c);
  }
  return out;
}

TEST(RepairCli, EachDefectIsRefusedNamedAndRepaired) {
  test::TempDir dir;
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const std::string in = dir.file(c.name + ".obj"), out = dir.file(c.name + ".ply");
    write_obj(in, c.positions, c.faces);
    const auto plain = run_command(gpsurf("infer " + in + " -o " + out));
    if (c.refusal.empty()) {
      EXPECT_EQ(plain.exit_code, 0) << plain.output;  // a manifold mesh as it is: read as now
    } else {
      EXPECT_EQ(plain.exit_code, 1) << plain.output;
      EXPECT_NE(plain.output.find(in + ": " + c.refusal + "\n"), std::string::npos) << plain.output;
      EXPECT_EQ(std::count(plain.output.begin(), plain.output.end(), '\n'), 1) << plain.output;
    }
    const auto repaired = run_command(gpsurf("infer " + in + " -o " + out + " --repair"));
    ASSERT_EQ(repaired.exit_code, 0) << repaired.output;
    EXPECT_EQ(repaired.output, c.report + "wrote " + out + "\n");
    const CovarianceMesh m = read_mesh(out);
    EXPECT_EQ(m.n_vertices(), c.vertices);
    EXPECT_EQ(m.n_faces(), c.faces_after);
    EXPECT_EQ(boundary_edges(m), c.boundary);
  }
}

TEST(RepairCli, EveryCommandThatReadsAMeshRepairs) {
  test::TempDir dir;
  const Case c = cases()[0];
  const std::string in = dir.file("pinch.obj");
  write_obj(in, c.positions, c.faces);
  const std::string report = c.report;
  for (const std::string& command :
       {"info " + in, "subdivide " + in + " -o " + dir.file("s.ply"), "tessellate " + in + " -o " + dir.file("t.obj"),
        "edit " + in + " -o " + dir.file("e.ply") + " --ops '[]'", "infer " + in + " -o " + dir.file("i.ply")}) {
    SCOPED_TRACE(command);
    EXPECT_EQ(run_command(gpsurf(command)).exit_code, 1);
    const auto r = run_command(gpsurf(command + " --repair"));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.output.rfind(report, 0), 0u) << "the report comes first: " << r.output;
  }
  EXPECT_EQ(run_command(gpsurf("edit " + in + " -o " + dir.file("q.ply") + " --ops '[]' --repair -q")).output, "");
}

TEST(RepairCli, WeldToleranceImpliesRepair) {
  test::TempDir dir;
  // Two triangles whose shared corners lie 1e-3 apart (the diagonal is about 1.4).
  const std::string in = dir.file("gap.obj");
  write_obj(in, {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1.001, 0, 0), Vec3(0, 1.001, 0), Vec3(1, 1, 0)},
            {{0, 1, 2}, {3, 5, 4}});
  const auto tight = run_command(gpsurf("info " + in + " --repair"));
  EXPECT_NE(tight.output.find("repair: nothing to repair\n"), std::string::npos) << tight.output;
  EXPECT_NE(tight.output.find("boundary edges: 6\n"), std::string::npos) << tight.output;
  const auto loose = run_command(gpsurf("info " + in + " --weld 0.01"));
  EXPECT_EQ(loose.exit_code, 0) << loose.output;
  EXPECT_NE(loose.output.find("repair: welded 4 coincident vertices into 2\n"), std::string::npos) << loose.output;
  EXPECT_NE(loose.output.find("boundary edges: 4\n"), std::string::npos) << loose.output;
  EXPECT_EQ(run_command(gpsurf("info " + in + " --weld -1")).exit_code, 2);
}

TEST(RepairCli, InfoListsEveryProblemAndExitsOne) {
  test::TempDir dir;
  // Two tetrahedra on one vertex, one face flipped, one duplicated, a fin quad and an isolated vertex.
  std::vector<Vec3> p;
  Faces faces;
  add_tetrahedron(p, faces, Vec3(0, 0, 0), -1, 1);
  add_tetrahedron(p, faces, Vec3(0, 0, 0), 0, -1);
  std::reverse(faces[5].begin() + 1, faces[5].end());
  faces.push_back(faces[7]);
  p.insert(p.end(), {Vec3(3, 3, 3), Vec3(-2, 2, 0)});
  faces.push_back({1, 2, 8});  // a third face on the edge 1–2
  const std::string in = dir.file("many.obj");
  write_obj(in, p, faces);
  const auto r = run_command(gpsurf("info " + in));
  EXPECT_EQ(r.exit_code, 1);
  for (const char* line :
       {"refused for (vertices and faces numbered from 1):\n",
        "  duplicate faces (on the vertices of an earlier one): 1 (face 9 (line 18) as face 8 (line 17))\n",
        "  non-manifold edges (fins: more than two faces): 1 (the edge of vertex 2 (line 2) and vertex 3 (line 3) "
        "with 3 faces)\n",
        "  non-manifold (pinch) vertices: 1 (vertex 1 (line 1) with 2 fans)\n",
        "  faces oriented against their neighbours: 1 (face 6 (line 15))\n",
        "also:\n  isolated vertices (in no face): 1 (vertex 8 (line 8))\n",
        "after --repair: 11 vertices, 9 faces, 3 parts, 1 boundary loop, genus 0, scheme Loop\n",
        ": 1 duplicate face (on the vertices of an earlier one), face 9 (line 18) as face 8 (line 17); --repair "
        "drops it; 1 non-manifold edge (a fin: more than two faces), the edge of vertex 2 (line 2) and vertex 3 "
        "(line 3) with 3 faces; --repair gives the extra faces their own vertices; 1 non-manifold (pinch) vertex, vertex 1 "
        "(line 1) with 2 fans; --repair splits it; 1 face oriented against its neighbours, face 6 (line 15); "
        "--repair flips it\n"})
    EXPECT_NE(r.output.find(line), std::string::npos) << line << " in\n" << r.output;
}

// A mesh read as it is: info says what it is read with (exit 0), numbered as the file numbers them,
// and what a repair would leave; the counts are those the mesh was built with.
TEST(RepairCli, InfoNamesWhatAReadMeshHasAndExitsZero) {
  test::TempDir dir;
  // The cube, its vertex 1 given again as vertex 9 (used by no face: coincident, then isolated once
  // welded), vertex 10 in no face, and a zero-area triangle on the edge 1–2 through vertex 11.
  std::vector<Vec3> p = cube_positions();
  p.insert(p.end(), {corner(0), Vec3(5, 5, 5), Vec3(0.5, 0, 0)});
  Faces faces = kCube;
  faces[4] = {0, 2, 3, 1, 10};  // the bottom runs 1→0 back through vertex 11 on the edge 0–1
  faces.push_back({0, 10, 1});
  const std::string in = dir.file("warn.obj");
  write_obj(in, p, faces);
  const auto r = run_command(gpsurf("info " + in));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  for (const char* line :
       {"vertices: 11\n", "surface: 1 part, 0 boundary loops, genus 0\n",
        "read as they are (--repair mends them; vertices and faces numbered from 1):\n",
        "  coincident vertices: 2 (vertex 9 (line 9) at vertex 1 (line 1))\n",
        "  zero-area faces: 1 (face 7 (line 18))\n", "  isolated vertices (in no face): 1 (vertex 10 (line 10))\n",
        // Dropping the zero-area face leaves the slit it covered open: a loop of zero area.
        "after --repair: 9 vertices, 6 faces, 1 part, 1 boundary loop, genus 0, scheme Catmull-Clark\n"})
    EXPECT_NE(r.output.find(line), std::string::npos) << line << " in\n" << r.output;
}

// Parts, boundary loops and genus against Euler's formula on meshes whose values are known: a torus
// of 4 × 4 quads (genus 1), and a cube beside an open square of 2 × 2 quads (2 parts, 1 loop).
TEST(RepairCli, InfoReportsPartsBoundaryLoopsGenusAndScheme) {
  test::TempDir dir;
  std::vector<Vec3> p;
  Faces faces;
  constexpr int n = 4;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = 2 * M_PI * i / n, v = 2 * M_PI * j / n;
      p.push_back(Vec3((3 + std::cos(v)) * std::cos(u), (3 + std::cos(v)) * std::sin(u), std::sin(v)));
    }
  const auto at = [&](int i, int j) { return (i % n) * n + j % n; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
  const std::string torus = dir.file("torus.obj");
  write_obj(torus, p, faces);
  const auto t = run_command(gpsurf("info " + torus));
  EXPECT_EQ(t.exit_code, 0) << t.output;
  EXPECT_NE(t.output.find("surface: 1 part, 0 boundary loops, genus 1\nscheme: Catmull-Clark\n"), std::string::npos)
      << t.output;
  EXPECT_EQ(t.output.find("read as they are"), std::string::npos) << "nothing to report: " << t.output;

  std::vector<Vec3> q = cube_positions();
  Faces g = kCube;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) q.push_back(Vec3(3 + i, j, 0));
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const int a = 8 + 3 * i + j;
      g.push_back({a, a + 3, a + 4, a + 1});
    }
  const std::string two = dir.file("two.obj");
  write_obj(two, q, g);
  const auto s = run_command(gpsurf("info " + two));
  EXPECT_EQ(s.exit_code, 0) << s.output;
  EXPECT_NE(s.output.find("surface: 2 parts, 1 boundary loop, genus 0\n"), std::string::npos) << s.output;
}

// The text after `prefix` in `output`, to the end of its line ("" where it is not there).
std::string line_after(const std::string& output, const std::string& prefix) {
  const size_t at = output.find(prefix);
  if (at == std::string::npos) return "";
  const size_t from = at + prefix.size();
  return output.substr(from, output.find('\n', from) - from);
}

// Fins whose extra faces stay joined to the kept ones through their other edges, with flipped faces: a
// closed tetrahedron with a triangle hanging from one edge (written first) and a face flipped; a cube
// with a cone over one face (a fin on each of its edges); a grid of quads with a tetrahedron on an
// interior edge, one of its faces flipped. What info says --repair makes is what the commands that read
// the file with --repair get: its counts (info --repair), its surface (tessellate --repair) and its faces
// (subdivide --levels 0 --repair).
TEST(RepairCli, InfoAfterRepairIsWhatRepairMakes) {
  test::TempDir dir;
  std::vector<Vec3> p = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 1, 0), Vec3(0.5, 0.3, 1), Vec3(0.5, -1, 0)};
  Faces faces = {{0, 1, 4}, {1, 0, 2}, {0, 1, 3}, {3, 1, 2}, {3, 0, 2}};
  const int cube = int(p.size());
  for (int i = 0; i < 8; ++i) p.push_back(corner(i) + Vec3(3, 0, 0));
  for (const auto& face : kCube) faces.push_back({cube + face[0], cube + face[1], cube + face[2], cube + face[3]});
  p.push_back(Vec3(3.5, 0.5, -1));  // the cone's apex, below the bottom {0, 2, 3, 1}
  const int apex = int(p.size()) - 1;
  const std::vector<int> bottom = {cube + 0, cube + 2, cube + 3, cube + 1};
  for (size_t k = 0; k < 4; ++k) faces.push_back({bottom[(k + 1) % 4], bottom[k], apex});
  const int grid = int(p.size());
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) p.push_back(Vec3(6 + i, j, 0));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int a = grid + 4 * i + j;
      faces.push_back({a, a + 4, a + 5, a + 1});
    }
  const int a = grid + 5, b = grid + 9;  // an interior edge of the grid
  p.insert(p.end(), {Vec3(7.5, 1.2, 1), Vec3(7.2, 0.8, -1)});
  const int c = int(p.size()) - 2, d = c + 1;
  faces.insert(faces.end(), {{b, a, c}, {a, b, d}, {d, b, c}, {d, a, c}});  // the last one flipped
  const std::string in = dir.file("fins.obj");
  write_obj(in, p, faces);

  const auto info = run_command(gpsurf("info " + in));
  EXPECT_EQ(info.exit_code, 1) << info.output;
  const std::string after = line_after(info.output, "after --repair: ");
  ASSERT_NE(after, "") << info.output;
  const auto repaired = run_command(gpsurf("info " + in + " --repair"));
  ASSERT_EQ(repaired.exit_code, 0) << repaired.output;
  const std::string vertices = line_after(repaired.output, "\nvertices: ");
  const std::string faces_line = line_after(repaired.output, "\nfaces: ");
  const std::string surface = line_after(repaired.output, "\nsurface: ");
  const std::string scheme = line_after(repaired.output, "\nscheme: ");
  EXPECT_EQ(after, vertices + " vertices, " + faces_line.substr(0, faces_line.find(' ')) + " faces, " + surface +
                       ", scheme " + scheme.substr(0, scheme.find(" (")));
  EXPECT_EQ(surface, "6 parts, 3 boundary loops, genus 0")
      << "each tetrahedron closed and apart from the triangle or grid, the cube closed and apart from the cone";

  const auto tessellated = run_command(gpsurf("tessellate " + in + " -o " + dir.file("t.obj") + " --level 2 --repair"));
  ASSERT_EQ(tessellated.exit_code, 0) << tessellated.output;
  EXPECT_EQ(line_after(run_command(gpsurf("info " + dir.file("t.obj"))).output, "\nsurface: "), surface);

  const auto subdivided = run_command(gpsurf("subdivide " + in + " -o " + dir.file("s.ply") + " --levels 0 --repair"));
  ASSERT_EQ(subdivided.exit_code, 0) << subdivided.output;
  const CovarianceMesh m = read_mesh(dir.file("s.ply"));
  EXPECT_EQ(std::to_string(m.n_vertices()), vertices);
  EXPECT_EQ(boundary_edges(m), 3 + 4 + 12) << "the triangle's, the cone's and the grid's";
}

// Two tetrahedra on one triangle that is kept between them: each of its edges has three faces, and
// the five vertices have more corners than a manifold mesh on them can. Every reader holds so small a
// file whole, so info names the fins and --repair gives what info said, in OBJ, PLY and OFF alike; the
// report counts the one face it separated once, though it lay on three fins.
TEST(RepairCli, AFaceWhoseEveryEdgeIsAFinIsMendedInEveryFormat) {
  test::TempDir dir;
  const std::vector<Vec3> p = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0.3, 0.3, 1), Vec3(0.3, 0.3, -1)};
  const Faces faces = {{0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {0, 4, 1}, {1, 4, 2}, {0, 2, 4}, {0, 2, 1}};
  std::ostringstream ply, off;
  ply << "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
         "element face 7\nproperty list uchar int vertex_indices\nend_header\n";
  off << "OFF\n5 7 0\n";
  for (const Vec3& x : p) {
    ply << x.x() << ' ' << x.y() << ' ' << x.z() << '\n';
    off << x.x() << ' ' << x.y() << ' ' << x.z() << '\n';
  }
  for (const auto& face : faces) {
    ply << "3 " << face[0] << ' ' << face[1] << ' ' << face[2] << '\n';
    off << "3 " << face[0] << ' ' << face[1] << ' ' << face[2] << '\n';
  }
  write_obj(dir.file("membrane.obj"), p, faces);
  dir.write("membrane.ply", ply.str());
  dir.write("membrane.off", off.str());
  for (const std::string name : {"membrane.obj", "membrane.ply", "membrane.off"}) {
    SCOPED_TRACE(name);
    const std::string in = dir.file(name);
    const auto info = run_command(gpsurf("info " + in));
    EXPECT_EQ(info.exit_code, 1) << info.output;
    EXPECT_NE(info.output.find("non-manifold edges (fins: more than two faces): 3"), std::string::npos) << info.output;
    EXPECT_EQ(line_after(info.output, "after --repair: "),
              "8 vertices, 7 faces, 2 parts, 1 boundary loop, genus 0, scheme Loop")
        << info.output;
    const auto repaired = run_command(gpsurf("info " + in + " --repair"));
    ASSERT_EQ(repaired.exit_code, 0) << repaired.output;
    EXPECT_EQ(
        repaired.output.rfind("repair: separated 1 face from 3 edges with more than two faces (3 vertex copies)\n", 0),
        0u)
        << repaired.output;
    EXPECT_EQ(line_after(repaired.output, "\nsurface: "), "2 parts, 1 boundary loop, genus 0");
    const auto tessellated =
        run_command(gpsurf("tessellate " + in + " -o " + dir.file("t.ply") + " --level 2 --repair"));
    EXPECT_EQ(tessellated.exit_code, 0) << tessellated.output;
    const auto compared = run_command(gpsurf("compare " + in + " " + dir.file("t.ply") + " --level 1"));
    EXPECT_EQ(compared.exit_code, 0) << "compare reads only A's points: " << compared.output;
  }
}

// A face of zero area whose third corner lies on an edge puts a third face on it: dropping it is what
// --repair does, so info gives it as why the mesh is refused.
TEST(RepairCli, InfoGivesAZeroAreaFinAsWhyTheMeshIsRefused) {
  test::TempDir dir;
  std::vector<Vec3> p = cube_positions();
  Faces faces;
  for (const auto& face : kCube)
    faces.push_back({face[0], face[1], face[2]}), faces.push_back({face[0], face[2], face[3]});
  p.push_back(Vec3(0, 0.5, 0));  // the middle of edge 0–2
  faces.push_back({0, 8, 2});
  const std::string in = dir.file("zero.obj");
  write_obj(in, p, faces);
  const auto info = run_command(gpsurf("info " + in));
  EXPECT_EQ(info.exit_code, 1) << info.output;
  EXPECT_NE(
      info.output.find("refused for (vertices and faces numbered from 1):\n  zero-area faces: 1 (face 13 (line 22))"),
      std::string::npos)
      << info.output;
  EXPECT_EQ(line_after(info.output, "after --repair: "),
            "8 vertices, 12 faces, 1 part, 0 boundary loops, genus 0, scheme Loop");
}

// A Möbius strip of six quads beside a tetrahedron with a triangle hanging from one edge: info names
// the fin it mends and, after --repair, the part it cannot orient, numbered as the file numbers it;
// a command given --repair is refused with the same part and what to do.
TEST(RepairCli, InfoNamesWhatRepairCannotMend) {
  test::TempDir dir;
  constexpr int n = 6;
  std::vector<Vec3> p = {Vec3(0, 0, 5), Vec3(1, 0, 5), Vec3(0.5, 1, 5), Vec3(0.5, 0.3, 6), Vec3(0.5, -1, 5)};
  Faces faces = {{0, 1, 4}, {1, 0, 2}, {0, 1, 3}, {3, 1, 2}, {2, 0, 3}};
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n;
    const Vec3 radial(std::cos(a), std::sin(a), 0);
    const Vec3 across = std::cos(a / 2) * radial + std::sin(a / 2) * Vec3(0, 0, 1);
    p.push_back(3 * radial + across);
    p.push_back(3 * radial - across);
  }
  for (int i = 0; i + 1 < n; ++i) faces.push_back({5 + 2 * i, 7 + 2 * i, 8 + 2 * i, 6 + 2 * i});
  faces.push_back({5 + 2 * n - 2, 6, 5, 5 + 2 * n - 1});  // the last quad joins the first edge backwards
  const std::string in = dir.file("mobius.obj");
  write_obj(in, p, faces);
  const auto info = run_command(gpsurf("info " + in));
  EXPECT_EQ(info.exit_code, 1);
  for (const char* line : {"  non-manifold edges (fins: more than two faces): 1 (the edge of vertex 1 (line 1) and "
                           "vertex 2 (line 2) with 3 faces)\n",
                           "after --repair: refused for (vertices and faces numbered from 1):\n"
                           "  parts that cannot be oriented (Möbius-like): 1 (the part of face 6 (line 23))\n"})
    EXPECT_NE(info.output.find(line), std::string::npos) << line << " in\n" << info.output;
  const auto tessellated = run_command(gpsurf("tessellate " + in + " -o " + dir.file("t.obj") + " --repair"));
  EXPECT_EQ(tessellated.exit_code, 1);
  EXPECT_NE(tessellated.output.find(in + ": 1 part that cannot be oriented (Möbius-like), the part of face 6 (line "
                                         "23); no repair orients it (delete faces across it to cut it open, then "
                                         "repair)\n"),
            std::string::npos)
      << tessellated.output;
}

}  // namespace
}  // namespace gps
