#pragma once
// The Google Benchmarks' main() body, shared by every bench/ program.

namespace gps::bench {

/// Runs the registered benchmarks under the programs' heap settings (core/support/freed_memory.h), so that
/// they time what gpsurf and the editor do: main() after the benchmarks are registered.
int run_benchmarks(int argc, char** argv);

}  // namespace gps::bench
