#!/usr/bin/env bash
# Data-race check of the threaded code with ThreadSanitizer and LLVM's Archer (which tells
# TSan what OpenMP's barriers and joins synchronise; with GCC's libgomp TSan cannot see
# them and reports every access across a barrier). Not part of the default test run: it
# needs clang and LLVM's OpenMP runtime (installed here from Debian when missing) and takes
# a few minutes.
#
# Builds ./build-tsan (clang-14, -fsanitize=thread, portable code) and runs, on 2 and 3
# OpenMP threads: the unit tests of the threaded force loop and its partition, the threaded
# integrator and neighbour search, and the job runner; then a shear series with two loads
# side by side (--jobs 2). Exits non-zero on any ThreadSanitizer report.
set -euo pipefail
cd "$(dirname "$0")/.."
archer=/usr/lib/llvm-14/lib/libarcher.so
if ! command -v clang++-14 >/dev/null || [ ! -e "$archer" ]; then
  sudo_cmd=""
  [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  $sudo_cmd apt-get install -y -q clang-14 libomp-14-dev >/dev/null
fi
CC=clang-14 CXX=clang++-14 cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCOLZA_NATIVE=OFF \
  -DCMAKE_CXX_FLAGS="-fsanitize=thread" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" >/dev/null
cmake --build build-tsan -j"$(nproc)" --target colza colza_unit_tests >/dev/null
export OMP_TOOL_LIBRARIES="$archer"
export TSAN_OPTIONS="ignore_noninstrumented_modules=1 halt_on_error=1 exitcode=66"
log=build-tsan/tsan.log
: >"$log"
for threads in 2 3; do
  echo "unit tests of the threaded code, OMP_NUM_THREADS=$threads"
  # (StartsNoJobAfterCtrlC starts threads in a forked child, which TSan does not support.)
  OMP_NUM_THREADS=$threads build-tsan/tests/colza_unit_tests \
    --gtest_filter='ForcePaths*:ForcePartition*:IntegrationSums*:NeighbourSearch*:OncePerKey*:RunConcurrently*:-RunConcurrently.StartsNoJobAfterCtrlC' \
    >>"$log" 2>&1 || { echo "FAILED (see $log)"; exit 1; }
done
echo "shear series, two loads side by side (--jobs 2)"
build-tsan/src/colza run shear-series --config tests/data/small_shear.toml --jobs 2 --quiet --force \
  --out build-tsan/shear-series >>"$log" 2>&1 || { echo "FAILED (see $log)"; exit 1; }
echo "no data race reported (log: $log)"
