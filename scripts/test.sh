#!/usr/bin/env bash
# Builds colza and runs the default test run: all CTest labels except `full`
# (full-size physics runs; run those with: ctest --test-dir build -L full).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
ctest --test-dir build -LE full --output-on-failure -j"$(nproc)" --timeout 1500
