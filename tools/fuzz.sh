#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (build/fuzz: ASan + UBSan + coverage) and runs them.
# Usage: tools/fuzz.sh [SECONDS] [TARGET...]     SECONDS per target (default 20); TARGET: obj set config script world
#   tools/fuzz.sh 20                 # what CI runs: each target 20 s, two at a time
#   tools/fuzz.sh 600 obj            # ten minutes of the OBJ importer
# Each target starts from fuzz/corpus/<target> and fuzz/regressions/<target> and adds what it finds
# to build/fuzz/corpus/<target> (never to the repository). A failure leaves the input in
# build/fuzz/artifacts/; fix it, then add the input to fuzz/regressions/<target>/ so the tests keep it.
# Environment: CLOTHTEAR_FUZZ_JOBS (targets at once, default 2), CLOTHTEAR_FUZZ_BUILD (build dir).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-20}"
shift || true
targets=("$@")
((${#targets[@]})) || targets=(obj set config script world)
build="${CLOTHTEAR_FUZZ_BUILD:-build/fuzz}"
jobs="${CLOTHTEAR_FUZZ_JOBS:-2}"
cxx="$(command -v clang++-14 || command -v clang++ || true)"
if [[ -z "$cxx" ]]; then
  echo "clothtear: fuzzing skipped: clang++ not found (tools/install-deps.sh installs clang-14)"
  exit 0
fi
# The configure log goes inside the build tree: beside it, a build dir such as build6-fuzz left
# build6-fuzz.configure.log in the repository's root.
mkdir -p "$build"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1" \
  -DCMAKE_CXX_COMPILER="$cxx" -DCLOTHTEAR_FUZZ=ON -DCLOTHTEAR_BUILD_APP=OFF -DCLOTHTEAR_BUILD_TESTS=OFF \
  -DCLOTHTEAR_BUILD_BENCH=OFF -DCLOTHTEAR_OPENMP=OFF > "$build/configure.log" 2>&1 || { cat "$build/configure.log"; exit 1; }
cmake --build "$build" -j "$(nproc)" --target "${targets[@]/#/fuzz_}"
mkdir -p "$build/artifacts"

# One target: libFuzzer's own time limit, its final statistics and coverage in one line.
run_one() {
  local t="$1" log="$build/fuzz_$1.log"
  mkdir -p "$build/corpus/$t"
  local status=0
  # git keeps no empty folders: a target with no regression yet has no fuzz/regressions/<target>.
  local dirs=("$build/corpus/$t" "fuzz/corpus/$t")
  [[ -d "fuzz/regressions/$t" ]] && dirs+=("fuzz/regressions/$t")
  "$build/fuzz/fuzz_$t" -max_total_time="$seconds" -print_final_stats=1 -artifact_prefix="$build/artifacts/$t-" \
    "${dirs[@]}" > "$log" 2>&1 || status=$?
  local execs cov
  execs=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
  cov=$(grep -E '^#[0-9]+' "$log" | tail -1 | grep -oE 'cov: [0-9]+ ft: [0-9]+ corp: [0-9]+/[0-9a-zA-Z]+' || echo "cov: ?")
  if ((status)); then
    echo "clothtear: fuzz_$t FAILED after ${execs} runs; input in $build/artifacts/ (log: $log):"
    grep -E 'clothtear fuzz:|ERROR: |SUMMARY' "$log" | head -5
    return 1
  fi
  echo "clothtear: fuzz_$t: ${seconds} s, ${execs} runs, ${cov}, no finding"
}

failed=0
running=0
for t in "${targets[@]}"; do
  run_one "$t" &
  running=$((running + 1))
  if ((running >= jobs)); then
    wait -n || failed=1
    running=$((running - 1))
  fi
done
while ((running > 0)); do
  wait -n || failed=1
  running=$((running - 1))
done
exit "$failed"
