#!/usr/bin/env bash
# What CI runs (.ci/run): installs what is missing, builds everything in Release and runs the whole
# test suite; then the core and tearing tests again under AddressSanitizer + UndefinedBehaviorSanitizer;
# then a short run of every fuzzer (tools/fuzz.sh). From a fresh clone on a 2-core VM running at about
# 0.4 x its usual speed: 1,412 s (Release build and tests 466 s, sanitizers 764 s, fuzzing 182 s) since
# the test files build at -O1 with precompiled headers (CMakeLists.txt, clothtear_test_build) and the
# core with one; 1,718 s before on such a day (616 / 892 / 210 s); CI's own run took 1,650 s then.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh
jobs="$(nproc)"
start=$SECONDS

cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build/release -j "$jobs"
ctest --test-dir build/release --output-on-failure -j "$jobs" --timeout 900
echo "clothtear: release build and tests: $((SECONDS - start)) s"

# Sanitizers (CLOTHTEAR_SANITIZE): core, runner and tests, no app. -O1 -g1 keeps the build and the run
# within CI's time; no NDEBUG, so Eigen's own range checks are on too. The ball experiments and the
# determinism runs (and the 6 m cloth of Limit.ASixMetre...) are left to the Release suite: they check physics outcomes and hashes, take
# minutes under ASan, and their code paths (collisions, tearing, threads) are in the tests that run here.
# So are the slowest outcome tests of pulls, balls and the law's hang (1-3 minutes each under ASan on a
# slow VM, 630 s of the 730 there): the same phases run in the shorter tests of the same groups.
asan_start=$SECONDS
cmake -S . -B build/asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1" \
  -DCLOTHTEAR_SANITIZE=ON -DCLOTHTEAR_BUILD_APP=OFF -DCLOTHTEAR_BUILD_BENCH=OFF
cmake --build build/asan -j "$jobs"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build/asan --output-on-failure -j "$jobs" --timeout 900 -E '^(BallExperiments|Determinism|Holds)\.|^Limit\.ASixMetre|^BallSleep\.ABallBesideASleepingPiece|^Collision\.ABallStretchesTheSameBand|^TearScenes\.(PulledSideways|SlantedPulls|PullRipIsTheSame)|^Kes\.ImplicitEulerHangs'
echo "clothtear: sanitizer build and tests: $((SECONDS - asan_start)) s"

# Fuzzing: each target 20 s from its seed corpus (skipped, saying so, without clang).
fuzz_start=$SECONDS
tools/fuzz.sh 20
echo "clothtear: fuzzing: $((SECONDS - fuzz_start)) s; all of tools/test.sh: $((SECONDS - start)) s"
