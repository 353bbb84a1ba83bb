// convexloc-bench entry point; run with --benchmark_format=json for machine-readable output
#include <benchmark/benchmark.h>

BENCHMARK_MAIN();
