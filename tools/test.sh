#!/usr/bin/env bash
# Installs what is missing, builds everything in Release and runs the whole test suite (CI runs this).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build/release -j "$(nproc)"
ctest --test-dir build/release --output-on-failure -j "$(nproc)" --timeout 900
