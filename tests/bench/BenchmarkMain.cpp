// The fabguide_bench program: every Google Benchmark in tests/bench, one binary (`make bench` runs it).
#include <benchmark/benchmark.h>

BENCHMARK_MAIN();
