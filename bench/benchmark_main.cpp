// main() of the benchmark programs whose benchmarks register themselves (BENCHMARK()).
#include "bench/run_benchmarks.h"

int main(int argc, char** argv) { return gps::bench::run_benchmarks(argc, argv); }
