#include "bench/run_benchmarks.h"

#include <benchmark/benchmark.h>

#include "core/support/freed_memory.h"

namespace gps::bench {

int run_benchmarks(int argc, char** argv) {
  keep_freed_memory();
  ::benchmark::Initialize(&argc, argv);
  if (::benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  ::benchmark::RunSpecifiedBenchmarks();
  ::benchmark::Shutdown();
  return 0;
}

}  // namespace gps::bench
