#!/usr/bin/env bash
# Installs what is missing, builds in Release and opens the app (extra arguments go to clothtear).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build/release -j "$(nproc)" --target clothtear
exec build/release/src/app/clothtear "$@"
