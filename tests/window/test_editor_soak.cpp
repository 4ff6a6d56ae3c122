// A random-input soak of gpsurf-editor, in a real window (ctest runs it under Xvfb):
// random event scripts (tests/support/random_events.h) on several samples, each replayed to the end
// without a crash or a hang, and every file the session saved (--save, Ctrl+S over the input) loads
// with every covariance finite and positive definite. Small here (GPS_SOAK_EVENTS, default 30
// events per sample); scripts/soak.sh runs it long with many seeds (GPS_SOAK_SEED).
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "../support/random_events.h"
#include "core/support/error.h"
#include "core/io/mesh_io.h"
#include "core/modelling/samples.h"
#include "core/io/text_file.h"

namespace gps {
namespace {

int env_int(const char* name, int fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::atoi(v) : fallback;
}

// Why a saved file is not a valid covariance mesh, or "" when it is.
std::string check_saved(const std::string& path) {
  CovarianceMesh mesh;
  try {
    mesh = read_mesh(path);
  } catch (const std::exception& e) {
    return path + " does not load: " + e.what();
  }
  if (mesh.n_vertices() == 0) return path + " has no vertices";
  for (size_t v = 0; v < mesh.n_vertices(); ++v) {
    const Mat3 c = mesh.covariance(v);
    if (!c.allFinite() || !mesh.mean(v).allFinite()) return path + ": vertex " + std::to_string(v) + " is not finite";
    if ((c - c.transpose()).cwiseAbs().maxCoeff() > 1e-9 * c.cwiseAbs().maxCoeff())
      return path + ": vertex " + std::to_string(v) + " is not symmetric";
    if (Eigen::LLT<Mat3>(c).info() != Eigen::Success)
      return path + ": vertex " + std::to_string(v) + " is not positive definite";
  }
  return "";
}

// The files a session may drop: other samples and broken ones.
std::vector<std::string> drop_files(const test::TempDir& dir) {
  write_mesh(dir.file("torus.ply"), make_sample("torus"));
  write_mesh(dir.file("cone-binary.ply"), make_sample("cone-pointy"), true);
  const std::string valid = read_text_file(dir.file("torus.ply"));
  dir.write("truncated.ply", valid.substr(0, valid.size() / 2));
  dir.write("garbage.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n1 2\nzz\n");
  dir.write("nan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  dir.write("empty.off", "");
  dir.write("notes.txt", "not a mesh");
  std::filesystem::create_directories(dir.file("folder.ply"));
  return {dir.file("torus.ply"),   dir.file("cone-binary.ply"), dir.file("truncated.ply"),
          dir.file("garbage.ply"), dir.file("nan.obj"),         dir.file("empty.off"),
          dir.file("notes.txt"),   dir.file("folder.ply"),      dir.file("missing.ply")};
}

class EditorSoak : public ::testing::TestWithParam<std::string> {};

TEST_P(EditorSoak, RandomEventsNeitherCrashNorHangAndEverySaveLoads) {
  const std::string sample = GetParam();
  const int n_events = env_int("GPS_SOAK_EVENTS", 30);
  const unsigned seed =
      unsigned(env_int("GPS_SOAK_SEED", 14)) * 7919u + unsigned(std::hash<std::string>{}(sample) % 1000);
  const test::TempDir dir;
  const CovarianceMesh mesh = make_sample(sample);
  const std::string input = dir.file(sample + ".ply");
  write_mesh(input, mesh);
  test::SoakSettings settings;
  settings.width = 480;
  settings.height = 360;
  settings.events = n_events;
  settings.drop_paths = drop_files(dir);
  const std::string events = dir.write("events.json", test::random_events(mesh, settings, seed));
  // A hang ends in `timeout` (exit 124); the editor itself exits 0 after the events.
  const int limit =
      env_int("GPS_SOAK_TIMEOUT", 300 + 2 * n_events);  // seconds; generous: CI machines are slow, sanitizers slower
  const test::CommandResult r = test::run_command(
      "cd " + dir.path().string() + " && XDG_CONFIG_HOME=" + dir.path().string() + " timeout -k 10 " +
      std::to_string(limit) + " " +
      test::editor_command(input + " --size " + std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                           " --play " + events + " --save " + dir.file("saved.ply")));
  const std::string where = sample + ", seed " + std::to_string(seed) + ", " + std::to_string(n_events) + " events";
  if (r.exit_code != 0)
    std::filesystem::copy_file(events, "soak-failed-" + sample + ".json",
                               std::filesystem::copy_options::overwrite_existing);
  ASSERT_NE(r.exit_code, 124) << where << ": hung (see soak-failed-" << sample << ".json)\n" << r.output;
  ASSERT_EQ(r.exit_code, 0) << where << " (see soak-failed-" << sample << ".json)\n" << r.output;
  EXPECT_EQ(r.output.find("Sanitizer"), std::string::npos) << where << "\n" << r.output;
  EXPECT_EQ(check_saved(dir.file("saved.ply")), "") << where;
  // Ctrl+S writes the open file: the input, or a valid mesh dropped on the window.
  for (const std::string& written : {input, dir.file("torus.ply"), dir.file("cone-binary.ply")})
    EXPECT_EQ(check_saved(written), "") << where;
  int screenshots = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
    screenshots += entry.path().extension() == ".png";
  std::printf("%s: %d random events replayed, saved files load, %d screenshots\n", where.c_str(), n_events,
              screenshots);
}

INSTANTIATE_TEST_SUITE_P(Samples, EditorSoak, ::testing::Values("cube", "cylinder", "icosphere", "pawn", "cone-pointy"),
                         [](const auto& info) {
                           std::string s = info.param;
                           std::replace(s.begin(), s.end(), '-', '_');
                           return s;
                         });

}  // namespace
}  // namespace gps
