// gpsurf render and diff, run as a user would (OSMesa, no display).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include <filesystem>

#include "core/io/mesh_io.h"
#include "core/modelling/mesh_arrays.h"
#include "core/modelling/samples.h"
#include "render/image/image_io.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

using test::gpsurf;
using test::run_command;

// Without --level or --pixels the tessellation is adaptive, its edge length set by the output size;
// --level forces a uniform level.
TEST(RenderCli, DefaultsToAdaptiveLevelsForTheOutputSize) {
  test::TempDir dir;
  ASSERT_EQ(run_command(gpsurf("sample pawn -o " + dir.file("p.ply"))).exit_code, 0);
  const std::string base = "render " + dir.file("p.ply") + " -o " + dir.file("p.png");
  for (const auto& [options, expected] :
       {std::pair{" --size 120x90", "adaptive 4 px"}, std::pair{" --size 700x500", "adaptive 5 px"},
        std::pair{" --size 120x90 --pixels 9", "adaptive 9 px"}, std::pair{" --size 120x90 --level 3", "level 3"}}) {
    const auto r = run_command(gpsurf(base + options));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find(std::string("patches, ") + expected + ","), std::string::npos)
        << options << ": " << r.output;
  }
  const Image png = read_image(dir.file("p.png"));
  int drawn = 0;
  for (int y = 0; y < png.height; ++y)
    for (int x = 0; x < png.width; ++x) drawn += png.at(x, y, 0) < 0.9f;
  EXPECT_GT(drawn, 500);
}

// The default camera frames the surface's silhouette, not a sphere around its bounding box: the drawn
// pixels reach across the image less its margin (5 % of the half-extent at each side) along one axis,
// fit along the other, and are centred, at either aspect and up axis.
TEST(RenderCli, TheSilhouetteFillsTheImage) {
  test::TempDir dir;
  for (const char* sample : {"cone", "torus"}) {
    ASSERT_EQ(run_command(gpsurf(std::string("sample ") + sample + " -o " + dir.file("m.ply"))).exit_code, 0);
    for (const char* options : {" --size 200x150", " --size 120x200", " --size 200x150 --up z"}) {
      const auto r = run_command(gpsurf("render " + dir.file("m.ply") + " -o " + dir.file("m.png") + options));
      ASSERT_EQ(r.exit_code, 0) << r.output;
      const Image png = read_image(dir.file("m.png"));
      int lo_x = png.width, hi_x = -1, lo_y = png.height, hi_y = -1;
      for (int y = 0; y < png.height; ++y)
        for (int x = 0; x < png.width; ++x)
          if (png.at(x, y, 0) < 0.97f || png.at(x, y, 1) < 0.97f || png.at(x, y, 2) < 0.97f)
            lo_x = std::min(lo_x, x), hi_x = std::max(hi_x, x + 1), lo_y = std::min(lo_y, y),
            hi_y = std::max(hi_y, y + 1);
      const std::string what = std::string(sample) + options;
      ASSERT_GE(hi_x, 0) << what;
      const double w = double(hi_x - lo_x) / png.width, h = double(hi_y - lo_y) / png.height;
      EXPECT_LE(std::max(w, h), 0.96) << what;
      EXPECT_GE(std::max(w, h), 0.93) << what;
      EXPECT_LE(std::abs((lo_x + hi_x) - png.width), 3) << what << ": not centred across";
      EXPECT_LE(std::abs((lo_y + hi_y) - png.height), 3) << what << ": not centred upward";
    }
  }
}

TEST(RenderCli, RendersAovsAndDifferenceImages) {
  test::TempDir dir;
  ASSERT_EQ(run_command(gpsurf("sample valence5 -o " + dir.file("v.ply"))).exit_code, 0);
  const auto r = run_command(gpsurf("render " + dir.file("v.ply") + " -o " + dir.file("v.png") +
                                    " --size 96x64 --level 6 --mesh --wireframe" +
                                    " --aov position=" + dir.file("p.exr") + " --aov normal=" + dir.file("n.exr")));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Image png = read_image(dir.file("v.png"));
  EXPECT_EQ(png.width, 96);
  EXPECT_EQ(png.height, 64);
  const Image position = read_image(dir.file("p.exr"));
  int covered = 0;
  for (int y = 0; y < position.height; ++y)
    for (int x = 0; x < position.width; ++x) covered += position.at(x, y, 3) > 0.5f;
  EXPECT_GT(covered, 500);
  ASSERT_EQ(run_command(gpsurf("render " + dir.file("v.ply") + " -o " + dir.file("r.png") +
                               " --size 96x64 --reference 4 --mode normals" + " --aov position=" + dir.file("rp.exr")))
                .exit_code,
            0);
  const auto d =
      run_command(gpsurf("diff " + dir.file("p.exr") + " " + dir.file("p.exr") + " -o " + dir.file("same.png")));
  EXPECT_EQ(d.exit_code, 0) << d.output;
  EXPECT_NE(d.output.find("max 0,"), std::string::npos) << d.output;
  const auto e =
      run_command(gpsurf("diff " + dir.file("p.exr") + " " + dir.file("rp.exr") + " -o " + dir.file("d.png")));
  EXPECT_EQ(e.exit_code, 0) << e.output;
  EXPECT_NE(e.output.find("position difference"), std::string::npos);
  // diff tells the AOVs apart by their channel names: normals get the normal difference, and a
  // position buffer against a normal buffer is refused.
  const auto n =
      run_command(gpsurf("diff " + dir.file("n.exr") + " " + dir.file("n.exr") + " -o " + dir.file("nn.png")));
  EXPECT_EQ(n.exit_code, 0) << n.output;
  EXPECT_NE(n.output.find("normal difference"), std::string::npos) << n.output;
  const auto mixed =
      run_command(gpsurf("diff " + dir.file("p.exr") + " " + dir.file("n.exr") + " -o " + dir.file("pn.png")));
  EXPECT_EQ(mixed.exit_code, 2) << mixed.output;
  EXPECT_NE(mixed.output.find("holds positions but"), std::string::npos) << mixed.output;
  EXPECT_EQ(run_command(gpsurf("render " + dir.file("v.ply") + " -o " + dir.file("a.png") +
                               " --size 32x32 --pixels 4 --matcap jade"))
                .exit_code,
            0);
}

// The number after `label` ("max ") in `gpsurf diff`'s line, or −1.
double figure_after(const std::string& text, const std::string& label) {
  const size_t at = text.find(label);
  return at == std::string::npos ? -1.0 : std::atof(text.c_str() + at + label.size());
}

// Needles of condition 1e12, past float sums of 9D points, render in double points
// (render/gl/point_precision.h): a framed picture of the whole torus, whose position AOV is the
// exact evaluator's (--exact) to the GPU's float output. They were a blank picture (exit 0), then
// refused; no input framed on its surface is left that shows none of it.
TEST(RenderCli, NeedlesOfCondition1e12RenderAsTheExactEvaluatorSays) {
  test::TempDir dir;
  write_mesh(dir.file("thin.ply"), test::thin_torus(1e6, true));
  for (const bool exact : {false, true}) {
    const std::string name = exact ? "e" : "g";
    const auto r =
        run_command(gpsurf("render " + dir.file("thin.ply") + " -o " + dir.file(name + ".png") + " --size 96x96" +
                           (exact ? " --exact" : "") + " --aov position=" + dir.file(name + "p.exr")));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_TRUE(std::filesystem::exists(dir.file(name + ".png")));
  }
  const auto p =
      run_command(gpsurf("diff " + dir.file("gp.exr") + " " + dir.file("ep.exr") + " -o " + dir.file("dp.png")));
  ASSERT_EQ(p.exit_code, 0) << p.output;
  EXPECT_LT(figure_after(p.output, "max "), 1e-4) << p.output;
}

// Pixels of two pictures that differ in some channel by more than 0.1.
int differing_pixels(const Image& a, const Image& b) {
  int n = 0;
  for (int j = 0; j < a.height; ++j)
    for (int i = 0; i < a.width; ++i)
      for (int c = 0; c < 3; ++c)
        if (std::abs(a.at(i, j, c) - b.at(i, j, c)) > 0.1f) {
          ++n;
          break;
        }
  return n;
}

int drawn_pixels(const Image& png) {
  int n = 0;
  for (int j = 0; j < png.height; ++j)
    for (int i = 0; i < png.width; ++i) n += png.at(i, j, 0) < 0.97f || png.at(i, j, 2) < 0.97f;
  return n;
}

// Needles and discs of condition 1e5 to 1e7 and one orientation, turned off the coordinate axes, make
// the torus sample's own surface (tests/support/test_meshes.h): from an explicit camera (the GPU, the
// exact evaluator, the reference, the mesh lines), at a uniform level and auto-framed, they render the
// torus sample's picture. The discs of 7e5 rendered blank from the camera (framed on the GPU's
// spikes), spikes at uniform levels, and auto-framed were refused as covering no pixel, with the
// surface right on the CPU.
TEST(RenderCli, ThinGaussiansOfOneOrientationRenderAsTheTorusSample) {
  test::TempDir dir;
  write_mesh(dir.file("torus.ply"), make_sample("torus"));
  const std::vector<std::string> options = {" --camera 30,20,12",
                                            " --camera 30,20,12 --exact",
                                            " --camera 30,20,12 --reference 3",
                                            " --camera 30,20,12 --mesh",
                                            " --level 2",
                                            ""};
  std::vector<Image> torus;
  for (const std::string& o : options) {
    const auto r =
        run_command(gpsurf("render " + dir.file("torus.ply") + " -o " + dir.file("t.png") + " --size 120x90" + o));
    ASSERT_EQ(r.exit_code, 0) << o << ": " << r.output;
    torus.push_back(read_image(dir.file("t.png")));
    ASSERT_GT(drawn_pixels(torus.back()), 1500) << o;
  }
  for (const bool needle : {true, false})
    for (const double condition : {1e5, 7e5, 1e7}) {
      const std::string what = std::string(needle ? "needles" : "discs") + " of condition " + std::to_string(condition);
      write_mesh(dir.file("thin.ply"), test::one_orientation_torus(condition, needle));
      for (size_t k = 0; k < options.size(); ++k) {
        const auto r = run_command(
            gpsurf("render " + dir.file("thin.ply") + " -o " + dir.file("n.png") + " --size 120x90" + options[k]));
        EXPECT_EQ(r.exit_code, 0) << what << options[k] << ": " << r.output;
        if (r.exit_code == 0) {
          EXPECT_LE(differing_pixels(torus[k], read_image(dir.file("n.png"))), 20) << what << options[k];
        }
      }
    }
}

// Framing is computed in the renderer's normalised frame: the torus moved 1e7 away, or scaled by 1e-4
// and moved, is framed as at the origin. Moved, it was framed smaller (its float world points rounded
// to whole units).
TEST(RenderCli, FramingIsTheSameWhereverTheMeshLiesAndAtAnyScale) {
  test::TempDir dir;
  const CovarianceMesh torus = make_sample("torus");
  const auto mapped = [&](double scale, const Vec3& offset) {
    CovarianceMesh out = torus;
    for (size_t i = 0; i < torus.n_vertices(); ++i) {
      out.set_mean(i, scale * torus.mean(i) + offset);
      out.set_covariance(i, scale * scale * torus.covariance(i));
    }
    return out;
  };
  const std::vector<std::pair<std::string, CovarianceMesh>> cases = {
      {"origin", torus}, {"moved", mapped(1.0, Vec3(1e7, -1e7, 1e7))}, {"small", mapped(1e-4, Vec3(3e3, 0.0, -2e3))}};
  std::vector<Image> images;
  for (const auto& [name, mesh] : cases) {
    write_mesh(dir.file(name + ".ply"), mesh);
    const auto r =
        run_command(gpsurf("render " + dir.file(name + ".ply") + " -o " + dir.file(name + ".png") + " --size 160x120"));
    ASSERT_EQ(r.exit_code, 0) << name << ": " << r.output;
    images.push_back(read_image(dir.file(name + ".png")));
  }
  EXPECT_GT(drawn_pixels(images[0]), 4000);
  EXPECT_LE(differing_pixels(images[0], images[1]), 10) << "moved";
  EXPECT_LE(differing_pixels(images[0], images[2]), 10) << "small";
}

// The refusal of an auto-framed image that shows nothing still fires for a surface that covers no
// pixel: a quad whose corners lie on one line has a segment for its limit surface. Nothing is written.
TEST(RenderCli, ASurfaceThatCoversNoPixelIsRefused) {
  test::TempDir dir;
  const std::vector<Vec3> corners = {{-1.0, 0.0, 0.0}, {-0.3, 0.0, 0.0}, {0.4, 0.0, 0.0}, {1.0, 0.0, 0.0}};
  write_mesh(dir.file("segment.ply"),
             make_covariance_mesh(corners, std::vector<Mat3>(4, 0.1 * Mat3::Identity()), {{0, 1, 2, 3}}, "segment"));
  const auto r =
      run_command(gpsurf("render " + dir.file("segment.ply") + " -o " + dir.file("s.png") + " --size 64x64"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("covers no pixel"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir.file("s.png")));
}

// --exact draws the patches' own triangles (at the default adaptive levels here) with the CPU's
// exact values: its AOVs differ from the patches' by the GPU's float error alone, under Loop (whose
// triangles no reference level has) and under Catmull-Clark on a mixed mesh.
TEST(RenderCli, ExactEvaluatorDrawsThePatchesOwnTriangles) {
  test::TempDir dir;
  for (const char* sample : {"icosphere", "pawn"}) {
    const std::string mesh = dir.file(std::string(sample) + ".ply");
    ASSERT_EQ(run_command(gpsurf("sample " + std::string(sample) + " -o " + mesh)).exit_code, 0);
    for (const bool exact : {false, true}) {
      const std::string name = exact ? "e" : "g";
      const auto r = run_command(gpsurf("render " + mesh + " -o " + dir.file(name + ".png") + " --size 160x120" +
                                        (exact ? " --exact" : "") + " --aov position=" + dir.file(name + "p.exr") +
                                        " --aov normal=" + dir.file(name + "n.exr")));
      ASSERT_EQ(r.exit_code, 0) << r.output;
      EXPECT_EQ(r.output.find("adaptive 4 px, exact evaluator,") != std::string::npos, exact) << r.output;
    }
    const auto p =
        run_command(gpsurf("diff " + dir.file("gp.exr") + " " + dir.file("ep.exr") + " -o " + dir.file("dp.png")));
    const auto n =
        run_command(gpsurf("diff " + dir.file("gn.exr") + " " + dir.file("en.exr") + " -o " + dir.file("dn.png")));
    ASSERT_EQ(p.exit_code, 0) << p.output;
    ASSERT_EQ(n.exit_code, 0) << n.output;
    // Above 0 (double is not float), and within the GPU's float error.
    EXPECT_GT(figure_after(p.output, "max "), 0.0) << p.output;
    EXPECT_LT(figure_after(p.output, "max "), 1e-4) << sample << ": " << p.output;
    EXPECT_GT(figure_after(n.output, "max "), 0.0) << n.output;
    EXPECT_LT(figure_after(n.output, "max "), 1e-3) << sample << ": " << n.output;
  }
  const std::string script =
      dir.write("s.json", R"({"renders": [{"mesh": "sample:cone", "output": ")" + dir.file("s.png") +
                              R"(", "size": "48x48", "level": 4, "exact": true}]})");
  const auto s = run_command(gpsurf("render --script " + script));
  EXPECT_EQ(s.exit_code, 0) << s.output;
  EXPECT_NE(s.output.find("level 4, exact evaluator,"), std::string::npos) << s.output;
  const auto both =
      run_command(gpsurf("render " + dir.file("pawn.ply") + " -o " + dir.file("x.png") + " --exact --reference 3"));
  EXPECT_EQ(both.exit_code, 2) << both.output;
  EXPECT_EQ(std::count(both.output.begin(), both.output.end(), '\n'), 1) << both.output;
}

// Under Catmull-Clark, --reference N draws the reference in the patches' own triangles at level 2^N:
// against the exact evaluator's values in the same triangles (equal to the reference's to 1e-14) the
// images are the same, which in the reference's own triangles they would not be (the two draws round
// differently). A triangle mesh under Catmull-Clark: half-size patches.
TEST(RenderCli, ReferenceDrawsInThePatchesTrianglesUnderCatmullClark) {
  test::TempDir dir;
  const std::string mesh = dir.file("cone.ply");
  ASSERT_EQ(run_command(gpsurf("sample cone-plateau -o " + mesh)).exit_code, 0);
  for (const std::string& how : {std::string("--exact --level 16"), std::string("--reference 4")}) {
    const auto r =
        run_command(gpsurf("render " + mesh + " -o " + dir.file("r.png") + " --size 256x256 --scheme catmull-clark " +
                           how + " --aov normal=" + dir.file(how[2] + std::string("n.exr"))));
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  const auto n =
      run_command(gpsurf("diff " + dir.file("en.exr") + " " + dir.file("rn.exr") + " -o " + dir.file("d.png")));
  ASSERT_EQ(n.exit_code, 0) << n.output;
  EXPECT_GE(figure_after(n.output, "max "), 0.0) << n.output;
  EXPECT_LT(figure_after(n.output, "max "), 1e-6) << n.output;
}

// A script renders several images in one process; an edit changes the image, and bad edits are refused.
TEST(RenderCli, ScriptedRendersWithEdits) {
  test::TempDir dir;
  const std::string script = dir.write("s.json", R"({"renders": [
    {"mesh": "sample:cube", "output": ")" + dir.file("a.png") +
                                                     R"(", "size": "48x48", "mode": "normals"},
    {"mesh": "sample:cube", "output": ")" + dir.file("b.png") +
                                                     R"(", "size": "48x48", "mode": "normals",
     "edits": [{"vertex": 6, "scale": 0.001}]}]})");
  const auto r = run_command(gpsurf("render --script " + script));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Image a = read_image(dir.file("a.png")), b = read_image(dir.file("b.png"));
  int changed = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) changed += std::abs(a.pixels[i] - b.pixels[i]) > 0.05f;
  EXPECT_GT(changed, 20);
  const std::string bad =
      dir.write("bad.json", R"({"renders": [{"mesh": "sample:cube", "output": "x.png", "edits": [{"vertex": 99}]}]})");
  const auto e = run_command(gpsurf("render --script " + bad));
  EXPECT_EQ(e.exit_code, 1);  // as gpsurf edit refuses a vertex past the mesh, in its words
  EXPECT_NE(e.output.find("render 0: edits[0]: vertex 99 is not in the mesh (8 vertices)"), std::string::npos)
      << e.output;
  EXPECT_EQ(run_command(gpsurf("render --script " + dir.write("broken.json", "{\"renders\": ["))).exit_code, 2);
}

// A script's numbers are taken only as the type they become: a vertex 4294967297 or 1.9 does not
// edit vertex 1, a level 2.5 is not level 2, and nothing is rendered.
TEST(RenderCli, ScriptNumbersOutsideTheirTypeAreRefused) {
  test::TempDir dir;
  const std::string out = dir.file("x.png");
  for (const auto& [job, message] : std::vector<std::pair<std::string, std::string>>{
           {R"("edits": [{"vertex": 4294967297, "scale": 2}])",
            "render 0: vertex must be an integer from 0 to 2147483647, got 4294967297"},
           {R"("edits": [{"vertex": 1.9, "scale": 2}])",
            "render 0: vertex must be an integer from 0 to 2147483647, got 1.9"},
           {R"("edits": [{"vertex": 1, "mean": [0, "1", 0]}])",
            "render 0: mean[1] must be a finite number, got a string"},
           {R"("level": 2.5)", "render 0: level must be an integer from 1 to 64, got 2.5"},
           {R"("exact": 1)", "render 0: exact must be true or false, got 1"},
           {R"("camera": 30)", "render 0: camera must be a string, got 30"},
           {R"("depth": 9)", "render 0: depth must be an integer from 0 to 8, got 9"},
           {R"("sigma": 1e400)", "renders[0].sigma: a number beyond the range of a double"},
           {R"("edits": {})", "render 0: edits: give a list of"},
           {R"("edits": [3])", "render 0: edits[0]: give {\"vertex\": i, ...}"},
           {R"("edits": [{"vertex": 0, "scale": 2}, {"vertex": 0, "scale": 1e-300}])",
            "render 0: edits[1]: vertex 0 has a covariance"},
           {R"("edits": [{"vertex": 0, "covariance": [1e-200, 0, 0, 1e-200, 0, 1e-200]}])",
            "render 0: edits[0]: vertex 0 has a covariance"},
           {R"("edits": [{"vertex": 0, "mean": [1e300, 0, 0]}])",
            "render 0: edits[0]: vertex 0 has a coordinate 1e+300 beyond"}}) {
    const std::string script = dir.write("s.json", R"({"renders": [{"mesh": "sample:cube", "output": ")" + out +
                                                       R"(", "size": "16x16", )" + job + "}]}");
    const auto r = run_command(gpsurf("render --script " + script));
    EXPECT_EQ(r.exit_code, 2) << job << "\n" << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("json.exception"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(out)) << job;
  }
}

// The EGL context (surfaceless Mesa here, a GPU driver's device elsewhere) renders what OSMesa renders.
TEST(RenderCli, EglAndOsMesaContextsAgree) {
  test::TempDir dir;
  run_command(gpsurf("sample valence6 -o " + dir.file("v.ply")));
  for (const char* kind : {"egl", "osmesa"}) {
    const auto r = run_command(gpsurf("render " + dir.file("v.ply") + " -o " + dir.file(std::string(kind) + ".png") +
                                      " --size 64x64 --context " + kind +
                                      " --aov position=" + dir.file(std::string(kind) + ".exr")));
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  const auto d =
      run_command(gpsurf("diff " + dir.file("egl.exr") + " " + dir.file("osmesa.exr") + " -o " + dir.file("d.png")));
  EXPECT_NE(d.output.find("max 0,"), std::string::npos) << d.output;
}

// A z-up mesh rendered with --up z is the picture of its y-up twin rendered as usual: the twin turned
// by the rotation that takes y to z (x ↦ x, y ↦ z, z ↦ −y), which GPS follows exactly.
TEST(RenderCli, UpAxisShowsAZUpMeshAsItsYUpTwin) {
  test::TempDir dir;
  const std::string rotate =
      R"(--ops '[{"op":"transform","vertices":"all","matrix":[1,0,0,0, 0,0,-1,0, 0,1,0,0, 0,0,0,1]}]')";
  ASSERT_EQ(run_command(gpsurf("edit sample:cone -o " + dir.file("z_up.ply") + " " + rotate)).exit_code, 0);
  ASSERT_EQ(run_command(gpsurf("sample cone -o " + dir.file("y_up.ply"))).exit_code, 0);
  const std::string options = " --size 160x120 --level 8";
  ASSERT_EQ(run_command(gpsurf("render " + dir.file("y_up.ply") + " -o " + dir.file("y.png") + options)).exit_code, 0);
  const auto r =
      run_command(gpsurf("render " + dir.file("z_up.ply") + " -o " + dir.file("z.png") + options + " --up z"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  ASSERT_EQ(run_command(gpsurf("render " + dir.file("z_up.ply") + " -o " + dir.file("z_as_y.png") + options)).exit_code,
            0);
  const Image y = read_image(dir.file("y.png")), z = read_image(dir.file("z.png")),
              z_as_y = read_image(dir.file("z_as_y.png"));
  const auto differing = [](const Image& a, const Image& b) {
    int n = 0;
    for (int j = 0; j < a.height; ++j)
      for (int i = 0; i < a.width; ++i)
        for (int c = 0; c < 3; ++c) n += std::abs(a.at(i, j, c) - b.at(i, j, c)) > 0.1f;
    return n;
  };
  EXPECT_LE(differing(y, z), 30);         // float rounding along the silhouette at most
  EXPECT_GT(differing(y, z_as_y), 2000);  // seen with y up, the same mesh lies on its side
  EXPECT_EQ(run_command(gpsurf("render " + dir.file("y_up.ply") + " -o " + dir.file("w.png") + " --up w")).exit_code,
            2);
}

// From a camera given, an image that shows none of the surface is refused too, naming the mesh's
// size: a camera a million units from the unit cube, and one close to a mesh a millionth its size.
TEST(RenderCli, AGivenCameraThatShowsNoneOfTheSurfaceIsRefused) {
  test::TempDir dir;
  CovarianceMesh tiny = make_sample("cube");
  write_mesh(dir.file("c.ply"), tiny);
  for (size_t i = 0; i < tiny.n_vertices(); ++i) {
    tiny.set_mean(i, 1e-6 * tiny.mean(i));
    tiny.set_covariance(i, 1e-12 * tiny.covariance(i));
  }
  write_mesh(dir.file("tiny.ply"), tiny);
  for (const auto& [mesh, camera] :
       std::vector<std::pair<std::string, std::string>>{{"c.ply", "30,20,1e6"}, {"tiny.ply", "30,20,10"}}) {
    const auto r = run_command(
        gpsurf("render " + dir.file(mesh) + " -o " + dir.file("x.png") + " --size 64x64 --camera " + camera));
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_NE(r.output.find("covers no pixel of the image from the camera '" + camera + "'"), std::string::npos)
        << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("x.png")));
  }
  const auto near = run_command(
      gpsurf("render " + dir.file("tiny.ply") + " -o " + dir.file("y.png") + " --size 64x64 --camera 30,20,1e-5"));
  EXPECT_EQ(near.exit_code, 0) << near.output;
  EXPECT_GT(drawn_pixels(read_image(dir.file("y.png"))), 200);
}

// A view straight down or up the up axis (pitch ±90°) of a mesh away from the origin is the view of
// the same mesh at the origin: the camera keeps its sideways axis wherever the target lies.
TEST(RenderCli, AViewAlongTheUpAxisOfAMeshAwayFromTheOriginIsDrawn) {
  test::TempDir dir;
  CovarianceMesh moved = make_sample("cube");
  write_mesh(dir.file("c.ply"), moved);
  for (size_t i = 0; i < moved.n_vertices(); ++i) moved.set_mean(i, moved.mean(i) + Vec3(10, 10, 10));
  write_mesh(dir.file("moved.ply"), moved);
  for (const std::string camera : {"0,90", "45,-90", "0,90,6"}) {
    int drawn[2];
    for (int k = 0; k < 2; ++k) {
      const std::string mesh = dir.file(k == 0 ? "c.ply" : "moved.ply"),
                        image = dir.file("v" + std::to_string(k) + ".png");
      const auto r = run_command(gpsurf("render " + mesh + " -o " + image + " --size 64x64 --camera " + camera));
      ASSERT_EQ(r.exit_code, 0) << camera << ": " << r.output;
      drawn[k] = drawn_pixels(read_image(image));
    }
    EXPECT_GT(drawn[0], 500) << camera;
    EXPECT_NEAR(drawn[1], drawn[0], 0.02 * drawn[0]) << camera;
  }
}

// An image is saved as every file is (core/io/atomic_file.h): a read-only target is refused and kept,
// a hard-linked one is written so that both names see the new image, a directory is refused by name.
TEST(RenderCli, ImagesAreSavedAsEveryFileIs) {
  test::TempDir dir;
  run_command(gpsurf("sample cube -o " + dir.file("c.ply")));
  const std::string render = "render " + dir.file("c.ply") + " --size 32x32 -o ";
  dir.write("ro.png", "old");
  std::filesystem::permissions(dir.file("ro.png"), std::filesystem::perms::owner_read);
  const auto read_only = run_command(gpsurf(render + dir.file("ro.png")));
  EXPECT_EQ(read_only.exit_code, 1) << read_only.output;
  EXPECT_EQ(test::file_text(dir.file("ro.png")), "old");
  dir.write("a.png", "old");
  std::filesystem::create_hard_link(dir.file("a.png"), dir.file("b.png"));
  const auto linked = run_command(gpsurf(render + dir.file("a.png")));
  ASSERT_EQ(linked.exit_code, 0) << linked.output;
  EXPECT_EQ(read_image(dir.file("b.png")).width, 32) << "the other name sees the new image";
  std::filesystem::create_directory(dir.file("d.png"));
  const auto folder = run_command(gpsurf(render + dir.file("d.png")));
  EXPECT_EQ(folder.exit_code, 1) << folder.output;
  EXPECT_EQ(folder.output.find("Success"), std::string::npos) << folder.output;
}

TEST(RenderCli, BadInputIsAUsageError) {
  test::TempDir dir;
  run_command(gpsurf("sample cube -o " + dir.file("c.ply")));
  run_command(gpsurf("render " + dir.file("c.ply") + " -o " + dir.file("a.png") +
                     " --size 16x16 --aov position=" + dir.file("a.exr")));
  run_command(gpsurf("render " + dir.file("c.ply") + " -o " + dir.file("b.png") +
                     " --size 24x16 --aov position=" + dir.file("b.exr")));
  const std::string mesh = dir.file("c.ply"), out = " -o " + dir.file("x.png");
  for (const std::string& args : std::vector<std::string>{
           "render " + mesh + out + " --matcap velvet", "render " + mesh + out + " --level 0",
           "render " + mesh + out + " --level 65", "render " + mesh + out + " --size 10by10",
           "render " + mesh + out + " --aov depth=" + dir.file("d.exr"), "render " + mesh + out + " --mode toon",
           "render " + mesh + out + " --background 2,0,0", "render " + mesh + out + " --background 0,-1,0",
           "render " + mesh + out + " --camera 30,20,-1", "render " + mesh + out + " --camera 30,20,0",
           "render " + mesh + out + " --camera ''", "render " + mesh + out + " --aov position=" + dir.file("x.png"),
           "render " + mesh + out + " --aov normal=" + dir.file("n.exr") + " --aov normal=" + dir.file("m.exr"),
           "diff " + dir.file("a.exr") + " " + dir.file("a.png") + out, "bench --render --levels 1,,4",
           "bench --preprocess --meshes sphere:0", "diff " + dir.file("a.exr") + " " + dir.file("b.exr") + out}) {
    const auto r = run_command(gpsurf(args));
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << args << ": " << r.output;
  }
  // Where a benchmark's figures go is checked before it measures for minutes.
  const auto plots = run_command(gpsurf("bench --render --plots " + dir.file("none/p")));
  EXPECT_EQ(plots.exit_code, 1) << plots.output;
  EXPECT_NE(plots.output.find("does not exist"), std::string::npos) << plots.output;
  // A file that is not there is a failure to read it, as in every command (exit 1).
  for (const std::string& args : std::vector<std::string>{
           "render " + dir.file("missing.ply") + out, "diff " + dir.file("a.exr") + " " + dir.file("missing.exr") + out,
           "render --script " + dir.file("missing.json")}) {
    const auto r = run_command(gpsurf(args));
    EXPECT_EQ(r.exit_code, 1) << args << ": " << r.output;
    EXPECT_NE(r.output.find("missing."), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(": no such file"), std::string::npos) << r.output;
  }
}

// The CPU reference is sized before it is made, for all it holds (its parameters, limit normals and
// triangles: about three times what subdivide alone does), so that the budget refuses it up front.
TEST(RenderCli, TheReferenceIsRefusedUpFrontWhereItWouldPassTheBudget) {
  test::TempDir dir;
  ASSERT_EQ(run_command(gpsurf("sample sphere --size 600 -o " + dir.file("s.ply"))).exit_code, 0);
  const std::string base = gpsurf("render " + dir.file("s.ply") + " -o " + dir.file("r.png") + " --size 64x48");
  // Level 4 makes 153,600 faces: subdivide's own estimate is about 38 MB, the reference's about 120 MB.
  const auto refused = run_command("GPSURF_MEMORY_LIMIT_BYTES=80000000 " + base + " --reference 4");
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_NE(refused.output.find("the reference at level 4 would make about"), std::string::npos) << refused.output;
  EXPECT_EQ(run_command("GPSURF_MEMORY_LIMIT_BYTES=80000000 " + base + " --reference 3").exit_code, 0);
}

// Parts so far apart that, framed together, each is under a pixel: the refusal says so (it blamed thin
// Gaussians).
TEST(RenderCli, PartsEachUnderAPixelAreNamedAsSuch) {
  const MeshArrays cube = arrays_of(make_sample("cube"));
  std::vector<Vec3> means;
  std::vector<Mat3> covariances;
  std::vector<std::vector<int>> faces;
  for (const auto& [scale, shift] :
       std::vector<std::pair<double, Vec3>>{{1.0, Vec3::Zero()}, {1e-3, Vec3(-1e5, 0, 0)}, {1e-5, Vec3(3, 0, 0)}}) {
    const int first = int(means.size());
    for (size_t v = 0; v < cube.means.size(); ++v) {
      means.push_back(scale * cube.means[v] + shift);
      covariances.push_back(scale * scale * cube.covariances[v]);
    }
    for (std::vector<int> face : cube.faces) {
      for (int& c : face) c += first;
      faces.push_back(face);
    }
  }
  test::TempDir dir;
  write_mesh(dir.file("apart.ply"), make_covariance_mesh(means, covariances, faces));
  const auto r =
      run_command(gpsurf("render " + dir.file("apart.ply") + " -o " + dir.file("a.png") + " --size 320x240"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("its parts lie so far apart that the largest is 0.0083 pixels across"), std::string::npos)
      << r.output;
}

// An image a pixel or two across: one part, framed, may fall between the pixels' centres; a refusal
// then says so (it spoke of parts lying far apart), and nothing is written.
TEST(RenderCli, AnImageTooSmallForTheSurfaceSaysSo) {
  test::TempDir dir;
  ASSERT_EQ(run_command(gpsurf("sample cube -o " + dir.file("cube.ply"))).exit_code, 0);
  for (const char* size : {"1x2", "2x1", "1x16", "1x1000"}) {
    const auto r =
        run_command(gpsurf("render " + dir.file("cube.ply") + " -o " + dir.file("a.png") + " --size " + size));
    EXPECT_EQ(r.exit_code, 1) << size << ": " << r.output;
    EXPECT_NE(r.output.find("at " + std::string(size) + " it is under 2 pixels across"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("a.png"))) << size;
  }
}

// A mesh too small or too large for the float camera was drawn as nothing and blamed on thin
// Gaussians: refused by its size; within the range it is drawn.
TEST(RenderCli, AMeshBeyondTheCamerasSizesIsRefusedBySize) {
  test::TempDir dir;
  for (const double scale : {1e-31, 1e-29, 1e29, 1e31}) {
    // The unit cube with every coordinate written times the scale.
    const std::string e = "e" + std::to_string(int(std::lround(std::log10(scale))));
    std::string scaled;
    for (int c = 0; c < 8; ++c)
      scaled += "v " + std::to_string(c & 1) + e + " " + std::to_string((c >> 1) & 1) + e + " " +
                std::to_string(c >> 2) + e + "\n";
    scaled += "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
    const std::string mesh = dir.write("cube.obj", scaled), image = dir.file("a.png");
    const auto r = run_command(gpsurf("render " + mesh + " -o " + image + " --size 64x48"));
    if (scale > 1e-30 && scale < 1e30) {
      EXPECT_EQ(r.exit_code, 0) << scale << ": " << r.output;
      EXPECT_TRUE(std::filesystem::exists(image)) << scale;
    } else {
      EXPECT_EQ(r.exit_code, 1) << scale << ": " << r.output;
      EXPECT_NE(r.output.find("cube.obj: the mesh spans "), std::string::npos) << r.output;
      EXPECT_NE(r.output.find("beyond the sizes a view frames (1e-30 to 1e30 across"), std::string::npos) << r.output;
      EXPECT_FALSE(std::filesystem::exists(image)) << scale;
    }
    std::filesystem::remove(image);
  }
}

// The ellipsoids are an overlay: they leave the AOVs to the surface (their shader's undefined position
// and normal outputs read as surface at random pixels, and a surface under a pixel passed or failed
// the coverage check from one run to the next), and a surface they frame too small is said so.
TEST(RenderCli, EllipsoidsLeaveTheAovsToTheSurface) {
  test::TempDir dir;
  ASSERT_EQ(run_command(gpsurf("sample cube -o " + dir.file("cube.ply"))).exit_code, 0);
  const auto r = run_command(gpsurf("render " + dir.file("cube.ply") + " -o " + dir.file("c.png") +
                                    " --size 64x48 --sigma 3 --ellipsoids --aov normal=" + dir.file("n.exr") +
                                    " --aov position=" + dir.file("p.exr")));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // Where the surface is, a unit normal and a point on the cube's rounded limit surface; elsewhere zero.
  const Image normal = read_image(dir.file("n.exr")), position = read_image(dir.file("p.exr"));
  int surface = 0, other = 0;
  for (int y = 0; y < normal.height; ++y)
    for (int x = 0; x < normal.width; ++x) {
      const Vec3 n(normal.at(x, y, 0), normal.at(x, y, 1), normal.at(x, y, 2)),
          p(position.at(x, y, 0), position.at(x, y, 1), position.at(x, y, 2));
      if (normal.at(x, y, 3) == 0 && position.at(x, y, 3) == 0 && n.isZero(0) && p.isZero(0)) continue;
      const bool on_surface = normal.at(x, y, 3) >= 1 && normal.at(x, y, 3) <= 4 && position.at(x, y, 3) >= 1 &&
                              std::abs(n.norm() - 1) < 1e-3 && p.cwiseAbs().maxCoeff() <= 1.0001;
      (on_surface ? surface : other) += 1;
    }
  EXPECT_GT(surface, 20);
  EXPECT_EQ(other, 0);
  for (int run = 0; run < 3; ++run) {
    const auto r = run_command(gpsurf("render " + dir.file("cube.ply") + " -o " + dir.file("f.png") +
                                      " --size 80x80 --ellipsoids --sigma 50"));
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("the ellipsoids at sigma 50 frame an image in which it is under 2 pixels across"),
              std::string::npos)
        << r.output;
  }
}

// A camera given so near the mesh that the view ends before the surface (inside the pawn): said so,
// with how far the view reaches (it said only that the surface covered no pixel).
TEST(RenderCli, ACameraSoNearThatTheViewEndsShortOfTheSurfaceSaysSo) {
  test::TempDir dir;
  ASSERT_EQ(run_command(gpsurf("sample pawn -o " + dir.file("p.ply"))).exit_code, 0);
  const auto r = run_command(
      gpsurf("render " + dir.file("p.ply") + " -o " + dir.file("q.png") + " --size 64x48 --camera 30,20,0.0001"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("the view reaches only 0.01 beyond the camera, 100 times its distance; give a larger "
                          "distance"),
            std::string::npos)
      << r.output;
}

// A pawn a millionth the size, 1e8 away: the CPU's --exact and --reference images are the GPU's
// (they spiked by a quarter of its size: the 9D points lost the digits of its size to its distance).
TEST(RenderCli, TheCpusImagesOfAMeshFarFromTheOriginAreTheGpus) {
  test::TempDir dir;
  ASSERT_EQ(run_command(gpsurf("sample pawn -o " + dir.file("p.ply"))).exit_code, 0);
  const auto moved = run_command(gpsurf("edit " + dir.file("p.ply") + " -o " + dir.file("far.ply") +
                                        " --ops '[{\"op\":\"transform\",\"vertices\":\"all\",\"matrix\":"
                                        "[1e-6,0,0,1e8, 0,1e-6,0,0, 0,0,1e-6,0, 0,0,0,1]}]'"));
  ASSERT_EQ(moved.exit_code, 0) << moved.output;
  const std::string base = "render " + dir.file("far.ply") + " --size 160x120 --level 8 -o ";
  for (const char* cpu : {" --exact", " --reference 3"}) {
    ASSERT_EQ(run_command(gpsurf(base + dir.file("gpu.png"))).exit_code, 0);
    const auto r = run_command(gpsurf(base + dir.file("cpu.png") + cpu));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const Image gpu = read_image(dir.file("gpu.png")), image = read_image(dir.file("cpu.png"));
    int drawn = 0, different = 0;
    for (int y = 0; y < gpu.height; ++y)
      for (int x = 0; x < gpu.width; ++x) {
        drawn += gpu.at(x, y, 0) < 0.97f;
        float d = 0;
        for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(gpu.at(x, y, c) - image.at(x, y, c)));
        different += d > 0.1f;
      }
    EXPECT_GT(drawn, 4000) << cpu;
    EXPECT_LT(different, drawn / 100) << cpu << ": " << different << " of " << drawn << " pixels differ";
  }
}

}  // namespace
}  // namespace gps
