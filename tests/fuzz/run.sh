#!/usr/bin/env bash
# Builds the scenario fuzzer with clang and runs it for SECONDS (default 60)
# from the project's scenarios and the seeds here. Findings (crash-*,
# leak-*, timeout-*) are written to the fuzz build directory; the status is
# non-zero if there are any.
#
#   tests/fuzz/run.sh [SECONDS] [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds="${1:-60}"
build="${2:-build-fuzz}"

cmake -S . -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DTABLETOP_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" -j4 --target tabletop_scenario_fuzzer

corpus="$build/fuzz-corpus"   # inputs found along the way; the seeds stay untouched
mkdir -p "$corpus"
cd "$build"
./tests/tabletop_scenario_fuzzer "fuzz-corpus" ../scenarios ../tests/fuzz/seeds \
  -dict=../tests/fuzz/scenario.dict -max_len=4096 -timeout=10 -rss_limit_mb=2048 \
  -max_total_time="$seconds" -print_final_stats=1
