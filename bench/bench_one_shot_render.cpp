// `gpsurf render` of one image, timed as a user runs it: the whole command (load, plans, compute
// passes, framing, the frame, the PNG) on a sphere sample of 10,000 to 1,000,000 faces at the
// default 800x600 and adaptive levels. The mesh is written once, outside the timing. GPSURF_BINARY
// times another gpsurf (an earlier build's) on the same meshes.
// Name: OneShotRender/<faces>.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

#include <unistd.h>

namespace {

// The gpsurf of this build, or another one named by GPSURF_BINARY (an earlier build's, to compare).
std::string gpsurf(const std::string& args) {
  const char* other = std::getenv("GPSURF_BINARY");
  return std::string(other && *other ? other : GPSURF_BINARY) + " " + args + " > /dev/null";
}

// A folder of its own for the meshes and the image, removed at exit.
struct Folder {
  std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("gpsurf_bench_one_shot_" + std::to_string(getpid()));
  Folder() { std::filesystem::create_directories(path); }
  ~Folder() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

const std::filesystem::path& folder() {
  static const Folder f;
  return f.path;
}

void BM_OneShotRender(benchmark::State& state) {
  const std::string faces = std::to_string(state.range(0));
  const std::string mesh = (folder() / ("sphere" + faces + ".ply")).string(), image = (folder() / "s.png").string();
  if (!std::filesystem::exists(mesh) && std::system(gpsurf("sample sphere --size " + faces + " -o " + mesh).c_str()))
    return state.SkipWithError("gpsurf sample failed");
  for (auto _ : state)
    if (std::system(gpsurf("render " + mesh + " -o " + image).c_str()) != 0)
      return state.SkipWithError("gpsurf render failed");
}

BENCHMARK(BM_OneShotRender)
    ->Name("OneShotRender")
    ->Arg(10000)
    ->Arg(1000000)
    ->Iterations(1)
    ->Repetitions(3)
    ->UseRealTime()
    ->Unit(benchmark::kSecond);

}  // namespace
