// gpsurf simplify as a user runs it: the count asked for, the report, triangulated quads, and errors.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/io/mesh_io.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

using test::gpsurf;
using test::run_command;

int lines(const std::string& text) { return int(std::count(text.begin(), text.end(), '\n')); }

TEST(SimplifyCli, KeepsTheVerticesAskedForAndReportsTheDistances) {
  test::TempDir dir;
  ASSERT_EQ(run_command(gpsurf("sample icosphere --size 1280 -o " + dir.file("ico.ply"))).exit_code, 0);
  const auto r =
      run_command(gpsurf("simplify " + dir.file("ico.ply") + " -o " + dir.file("coarse.ply") + " --vertices 100"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("simplified 642 vertices, 1280 triangles to 100 vertices, 196 triangles\n"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("asked"), std::string::npos) << r.output;
  for (const char* figure : {"\nrms ", "\n99th percentile ", "\nmax "})
    EXPECT_NE(r.output.find(figure), std::string::npos) << figure << " in " << r.output;
  const CovarianceMesh coarse = read_mesh(dir.file("coarse.ply"));
  EXPECT_EQ(coarse.n_vertices(), 100u);
  EXPECT_EQ(gaussians_problem(coarse), "");

  const auto half = run_command(
      gpsurf("simplify " + dir.file("ico.ply") + " -o " + dir.file("half.ply") + " --ratio 0.5 --level 0 --ascii"));
  ASSERT_EQ(half.exit_code, 0) << half.output;
  EXPECT_NE(half.output.find("to 321 vertices"), std::string::npos) << half.output;
  EXPECT_EQ(half.output.find("rms"), std::string::npos) << half.output;  // --level 0: no report
  EXPECT_EQ(read_mesh(dir.file("half.ply")).n_vertices(), 321u);
}

TEST(SimplifyCli, FansQuadsIntoTrianglesAndSaysWhereItStopsShort) {
  test::TempDir dir;
  ASSERT_EQ(run_command(gpsurf("sample torus -o " + dir.file("torus.ply"))).exit_code, 0);
  const auto torus =
      run_command(gpsurf("simplify " + dir.file("torus.ply") + " -o " + dir.file("t.ply") + " --vertices 50"));
  ASSERT_EQ(torus.exit_code, 0) << torus.output;
  EXPECT_EQ(torus.output.rfind("fanned the faces of more than 3 sides into triangles\n", 0), 0u) << torus.output;
  EXPECT_NE(torus.output.find("to 50 vertices"), std::string::npos) << torus.output;

  // A tetrahedron has no collapse that keeps its topology: it stays as it is, and says so.
  const std::string tetrahedron =
      dir.write("tet.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  const auto stuck = run_command(gpsurf("simplify " + tetrahedron + " -o " + dir.file("s.ply") + " --vertices 4"));
  ASSERT_EQ(stuck.exit_code, 0) << stuck.output;
  EXPECT_NE(stuck.output.find("to 4 vertices, 4 triangles\n"), std::string::npos) << stuck.output;
  const std::string octahedron = dir.write("oct.obj",
                                           "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
                                           "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n");
  const auto octa = run_command(gpsurf("simplify " + octahedron + " -o " + dir.file("o.ply") + " --vertices 4"));
  ASSERT_EQ(octa.exit_code, 0) << octa.output;
  const size_t kept = read_mesh(dir.file("o.ply")).n_vertices();
  if (kept > 4) {
    EXPECT_NE(octa.output.find("(asked 4: no further collapse keeps"), std::string::npos) << octa.output;
  }
}

// --error stops where a collapse would move the surface further than E of the diagonal: a larger E
// keeps fewer vertices, and the input's rms distance to the result's faces is about E.
TEST(SimplifyCli, ErrorStopsAtADistance) {
  test::TempDir dir;
  ASSERT_EQ(run_command(gpsurf("sample icosphere --size 5120 -o " + dir.file("ico.ply"))).exit_code, 0);
  size_t previous = 2562;
  for (const double error : {0.003, 0.01, 0.03}) {
    const std::string out = dir.file("s" + std::to_string(error) + ".ply");
    const auto r = run_command(
        gpsurf("simplify " + dir.file("ico.ply") + " -o " + out + " --level 0 --error " + std::to_string(error)));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("(no further collapse keeps within --error"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("faces' normals within 45° (--max-normal-deviation))"), std::string::npos) << r.output;
    const size_t kept = read_mesh(out).n_vertices();
    EXPECT_LT(kept, previous) << error;
    previous = kept;
    const auto d = run_command(gpsurf("compare " + dir.file("ico.ply") + " " + out + " --linear"));
    ASSERT_EQ(d.exit_code, 0) << d.output;
    const size_t at = d.output.find("\nrms ");
    ASSERT_NE(at, std::string::npos) << d.output;
    const double rms = std::stod(d.output.substr(d.output.find('(', at) + 1));
    EXPECT_GT(rms, 0.3 * error) << d.output;
    EXPECT_LT(rms, 1.5 * error) << d.output;
  }
}

// --quads pairs the result's triangles into quads: the report counts them and the file has them.
TEST(SimplifyCli, QuadsPairTheTriangles) {
  test::TempDir dir;
  ASSERT_EQ(run_command(gpsurf("sample icosphere --size 5120 -o " + dir.file("ico.ply"))).exit_code, 0);
  const auto r = run_command(
      gpsurf("simplify " + dir.file("ico.ply") + " -o " + dir.file("q.ply") + " --vertices 300 --quads --level 0"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const CovarianceMesh m = read_mesh(dir.file("q.ply"));
  size_t quads = 0;
  for (size_t f = 0; f < m.n_faces(); ++f) quads += m.face_size(f) == 4;
  EXPECT_GT(quads, 0u);
  EXPECT_NE(r.output.find(", " + std::to_string(quads) + " pairs of them joined into quads (" +
                          std::to_string(m.n_faces()) + " faces)"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(m.n_vertices(), 300u);
}

// --limit moves the vertices out for the limit surface: it says by how much, the report's distances
// fall, and the faces and covariances are those of the simplification without it.
TEST(SimplifyCli, LimitPlacesTheVerticesForTheLimitSurface) {
  test::TempDir dir;
  ASSERT_EQ(run_command(gpsurf("sample icosphere --size 5120 -o " + dir.file("ico.ply"))).exit_code, 0);
  const std::string base = "simplify " + dir.file("ico.ply") + " --vertices 200 -o ";
  const auto plain = run_command(gpsurf(base + dir.file("plain.ply")));
  const auto placed = run_command(gpsurf(base + dir.file("placed.ply") + " --limit"));
  ASSERT_EQ(plain.exit_code, 0) << plain.output;
  ASSERT_EQ(placed.exit_code, 0) << placed.output;
  EXPECT_NE(placed.output.find("\nmoved the vertices out for the limit surface: its rms distance from the positions "
                               "kept, "),
            std::string::npos)
      << placed.output;
  const auto rms = [](const std::string& output) {
    const size_t at = output.find("\nrms ");
    return at == std::string::npos ? -1.0 : std::stod(output.substr(at + 5));
  };
  EXPECT_GT(rms(plain.output), 0);
  EXPECT_LT(rms(placed.output), 0.5 * rms(plain.output)) << plain.output << placed.output;
  const CovarianceMesh a = read_mesh(dir.file("plain.ply")), b = read_mesh(dir.file("placed.ply"));
  ASSERT_EQ(a.n_vertices(), b.n_vertices());
  ASSERT_EQ(a.topology().verts, b.topology().verts);
  int moved = 0;
  for (size_t v = 0; v < a.n_vertices(); ++v) {
    EXPECT_EQ(a.covariance(v), b.covariance(v));
    moved += (a.mean(v) - b.mean(v)).norm() > 0;
  }
  EXPECT_EQ(moved, int(a.n_vertices()));
}

TEST(SimplifyCli, UsageAndRuntimeErrorsAreOneLine) {
  test::TempDir dir;
  ASSERT_EQ(run_command(gpsurf("sample icosphere --size 320 -o " + dir.file("ico.ply"))).exit_code, 0);
  const std::string base = "simplify " + dir.file("ico.ply") + " -o " + dir.file("x.ply");
  for (const std::string& args :
       {std::string(""), std::string("--vertices 3"), std::string("--ratio 0"), std::string("--ratio 1.5"),
        std::string("--vertices 10 --ratio 0.5"), std::string("--ratio 0.01"), std::string("--vertices 10 --level 65"),
        std::string("--vertices 10 --bias 0"), std::string("--error 0"), std::string("--error 2"),
        std::string("--error nan")}) {
    const auto r = run_command(gpsurf(base + " " + args));
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.output;
    EXPECT_EQ(lines(r.output), 1) << args << ": " << r.output;
  }
  const auto missing =
      run_command(gpsurf("simplify " + dir.file("none.obj") + " -o " + dir.file("x.ply") + " --vertices 10"));
  EXPECT_EQ(missing.exit_code, 1) << missing.output;
  EXPECT_EQ(lines(missing.output), 1) << missing.output;
  EXPECT_NE(missing.output.find("none.obj"), std::string::npos) << missing.output;
  const auto unwritable =
      run_command(gpsurf("simplify " + dir.file("ico.ply") + " -o " + dir.file("no/such/x.ply") + " --vertices 10"));
  EXPECT_EQ(unwritable.exit_code, 1) << unwritable.output;
  EXPECT_NE(unwritable.output.find("x.ply"), std::string::npos) << unwritable.output;
}

}  // namespace
}  // namespace gps
