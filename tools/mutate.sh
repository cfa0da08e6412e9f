#!/usr/bin/env bash
# Mutation run: does the test suite notice a wrong change to the core? Each mutation of the list
# (tools/mutations.txt: an id, what it breaks, the tests of that behaviour, the exact text to
# replace and its replacement) is applied alone to a copy of the tree, the tests and the runner
# are rebuilt, and the suite runs against it. Per mutation:
#   killed (behaviour)  a test of the mutated behaviour failed
#   killed (other)      only other tests failed (a golden hash, a scene outcome: caught by chance)
#   survived            every test passed
# and the score "killed by a behaviour test: N of M (P %)".
#
#   tools/mutate.sh                    every mutation (about 30-40 min on 2 busy cores)
#   tools/mutate.sh wind-sign ball-push   only these
#   tools/mutate.sh --check            only check that every snippet occurs exactly once in src/
#                                      (of the checkout itself, nothing copied or built; a ctest)
# Options: --list FILE (default tools/mutations.txt), --dir DIR (work directory, default
# ${TMPDIR:-/tmp}/clothtear-mutate-<checksum of the checkout's path>), --full (run the whole suite for every mutation, not only for
# those the behaviour tests miss), --no-baseline (skip the unmutated run).
# Environment: CLOTHTEAR_MUTATE_JOBS (build and ctest jobs, default 2), CLOTHTEAR_MUTATE_TIMEOUT
# (seconds per test, default 300: a mutation may make a test hang).
#
# The snippets are found by searching the whole of src/, never by file or line: files move. A
# snippet that is not there exactly once stops the run before anything is built, naming the
# mutation. The developer's checkout is never touched: the tree (with uncommitted changes, without
# build directories) is copied to DIR/tree (only changed files are rewritten, so later runs rebuild
# little) and built in DIR/build with the app and the benchmarks
# off, so only clothtear_tests and the headless `clothtear` are built. The app's tests
# (clothtear_app_tests, AppWindow.* among them) are therefore not run: they test the app over the
# same core, and the window tests need Xvfb and take minutes.
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
list="$root/tools/mutations.txt"
work="${TMPDIR:-/tmp}/clothtear-mutate-$(printf %s "$root" | cksum | cut -d ' ' -f 1)" # one per checkout
full=0 baseline=1 checkOnly=0
only=()
while [ $# -gt 0 ]; do
    case "$1" in
    --list) list="$(cd "$(dirname "$2")" && pwd)/$(basename "$2")"; shift 2 ;;
    --dir) work="$2"; shift 2 ;;
    --full) full=1; shift ;;
    --no-baseline) baseline=0; shift ;;
    --check) checkOnly=1; shift ;;
    -h | --help) sed -n '2,28p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "mutate.sh: unknown option $1" >&2; exit 2 ;;
    *) only+=("$1"); shift ;;
    esac
done
jobs="${CLOTHTEAR_MUTATE_JOBS:-2}"
timeout="${CLOTHTEAR_MUTATE_TIMEOUT:-300}"
tree="$work/tree" build="$work/build" logs="$work/logs"
mkdir -p "$work" "$logs"

# The list, checks and edits are done by this helper (python3: Debian's, no packages).
helper="$work/mutate_helper.py"
cat >"$helper" <<'PY'
import os, re, sys, xml.etree.ElementTree as ET

def parse(path):
    """The mutation blocks of `path`: dicts with id, what, tests (list) and pairs [(from, to)]."""
    muts, cur = [], None
    for n, raw in enumerate(open(path, encoding="utf-8"), 1):
        line = raw.rstrip("\n")
        if line.startswith("#"):
            continue
        if not line.strip():
            cur = None
            continue
        key, sep, value = line.partition(":")
        if not sep:
            sys.exit(f"{path}:{n}: expected 'key: value', got: {line}")
        key, value = key.strip(), value.strip()
        if cur is None:
            if key != "id":
                sys.exit(f"{path}:{n}: a mutation starts with 'id:'")
            cur = {"id": value, "what": "", "tests": [], "pairs": [], "line": n}
            muts.append(cur)
        elif key == "what":
            cur["what"] = value
        elif key == "tests":
            cur["tests"] = value.split()
        elif key == "from":
            cur["pairs"].append([value, None])
        elif key == "to":
            if not cur["pairs"] or cur["pairs"][-1][1] is not None:
                sys.exit(f"{path}:{n}: 'to:' without its 'from:'")
            cur["pairs"][-1][1] = value
        else:
            sys.exit(f"{path}:{n}: unknown key '{key}'")
    ids = set()
    for m in muts:
        where = f"{path}:{m['line']}: mutation '{m['id']}'"
        if not re.fullmatch(r"[A-Za-z0-9-]+", m["id"]) or m["id"] in ids:
            sys.exit(f"{where}: the id must be unique, letters, digits and '-'")
        ids.add(m["id"])
        if not m["tests"] or not m["pairs"] or any(t is None for _, t in m["pairs"]):
            sys.exit(f"{where}: needs tests:, and from: with to:")
    return muts

def pattern(snippet):
    """Regex for a snippet: its tokens in order, any whitespace between them."""
    return re.compile(r"\s+".join(re.escape(tok) for tok in snippet.replace("\\n", "\n").split()))

def sources(src):
    for d, _, files in sorted(os.walk(src)):
        for f in sorted(files):
            if f.endswith((".cpp", ".h", ".hpp", ".inl", ".cc")):
                yield os.path.join(d, f)

def locate(src, snippet):
    """[(file, match)] of every occurrence of snippet in the sources under src."""
    rx, hits = pattern(snippet), []
    for path in sources(src):
        text = open(path, encoding="utf-8").read()
        hits += [(path, m) for m in rx.finditer(text)]
    return hits

def select(muts, only):
    if not only:
        return muts
    known = {m["id"] for m in muts}
    missing = [o for o in only if o not in known]
    if missing:
        sys.exit("no mutation named " + ", ".join(missing))
    return [m for m in muts if m["id"] in only]

def cmd_check(listfile, src, *only):
    """Every snippet of the selected mutations occurs exactly once in src; prints the ids."""
    bad = []
    for m in select(parse(listfile), only):
        for frm, _ in m["pairs"]:
            hits = locate(src, frm)
            if len(hits) != 1:
                files = sorted({os.path.relpath(p, os.path.dirname(src)) for p, _ in hits})
                bad.append(f"mutation '{m['id']}': snippet found {len(hits)} times in src/"
                           + (f" ({', '.join(files)})" if files else "") + f": {frm}")
    if bad:
        sys.exit("mutate.sh: the list does not match the tree:\n  " + "\n  ".join(bad))
    for m in select(parse(listfile), only):
        print(m["id"])

def cmd_field(listfile, mid, field):
    m = next(m for m in parse(listfile) if m["id"] == mid)
    if field == "regex":  # ctest -R regex of the behaviour tests
        print("|".join("^" + re.escape(t).replace(r"\*", ".*") + "$" for t in m["tests"]))
    else:
        print(m[field] if isinstance(m[field], str) else " ".join(m[field]))

def cmd_apply(listfile, src, mid):
    """Applies mutation mid to the sources under src; prints the files it changed."""
    m = next(m for m in parse(listfile) if m["id"] == mid)
    changed = []
    for frm, to in m["pairs"]:
        (path, match), = locate(src, frm)
        text = open(path, encoding="utf-8").read()
        text = text[:match.start()] + to.replace("\\n", "\n") + text[match.end():]
        open(path, "w", encoding="utf-8").write(text)
        changed.append(path)
    print("\n".join(sorted(set(changed))))

def cmd_sync(src, dst):
    """Makes dst a copy of src without .git and build directories. Only files whose content
    differs are written (with a new time stamp), so the build in DIR/build recompiles exactly what
    changed since the last run, including files a run left mutated."""
    def skip(rel):
        top = rel.split(os.sep)[0]
        return top == ".git" or top.startswith("build")
    wanted = set()
    for d, dirs, files in os.walk(src):
        rel_d = os.path.relpath(d, src)
        dirs[:] = sorted(x for x in dirs if not skip(os.path.normpath(os.path.join(rel_d, x))))
        for f in files:
            rel = os.path.normpath(os.path.join(rel_d, f))
            if skip(rel) or os.path.islink(os.path.join(d, f)):
                continue
            wanted.add(rel)
            data = open(os.path.join(d, f), "rb").read()
            out = os.path.join(dst, rel)
            if os.path.exists(out) and open(out, "rb").read() == data:
                continue
            os.makedirs(os.path.dirname(out), exist_ok=True)
            open(out, "wb").write(data)
            os.chmod(out, os.stat(os.path.join(d, f)).st_mode & 0o777)
    for d, _, files in os.walk(dst):
        for f in files:
            rel = os.path.relpath(os.path.join(d, f), dst)
            if rel not in wanted:
                os.remove(os.path.join(d, f))

def cmd_failed(junit):
    """Names of the tests that did not pass in a ctest JUnit file."""
    for case in ET.parse(junit).getroot().iter("testcase"):
        if case.get("status") != "run" or case.find("failure") is not None:
            print(case.get("name"))

def cmd_count(junit):
    print(sum(1 for _ in ET.parse(junit).getroot().iter("testcase")))

if __name__ == "__main__":
    globals()["cmd_" + sys.argv[1]](*sys.argv[2:])
PY
py() { python3 "$helper" "$@"; }

# checkList SRC: every selected snippet occurs once in SRC; their ids into `ids`.
checkList() {
    local idText
    idText="$(py check "$list" "$1" "${only[@]}")" || exit 1
    mapfile -t ids <<<"$idText"
    echo "mutate.sh: ${#ids[@]} mutations, every snippet found exactly once in src/"
}

# ---- the check alone reads the checkout's own sources (a ctest runs it: tests/CMakeLists.txt)
if [ "$checkOnly" = 1 ]; then
    checkList "$root/src"
    exit 0
fi

# ---- the copy of the tree
echo "mutate.sh: syncing $root to $tree (no .git, no build directories)"
py sync "$root" "$tree"
rm -rf "$work/pristine"
cp -a "$tree/src" "$work/pristine"
checkList "$tree/src"

# ---- build and test helpers
cmake -S "$tree" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCLOTHTEAR_BUILD_APP=OFF \
    -DCLOTHTEAR_BUILD_BENCH=OFF >"$logs/configure.log"
buildIt() { cmake --build "$build" -j "$jobs" --target clothtear_tests clothtear >"$1" 2>&1; }
# runTests JUNIT LOG [ctest filter args...]: the failed test names go to stdout. Never the check of
# the list itself (label mutation-list, tests/CMakeLists.txt): a mutated tree no longer holds its own
# snippet, so it would fail for every mutation and count each as killed.
runTests() {
    local junit="$1" log="$2"
    shift 2
    rm -f "$junit"
    ctest --test-dir "$build" -j "$jobs" --timeout "$timeout" --output-junit "$junit" -LE '^mutation-list$' "$@" \
        >"$log" 2>&1 || true
    [ -f "$junit" ] || { echo "mutate.sh: ctest wrote no results, see $log" >&2; exit 1; }
    py failed "$junit"
}
# Puts src/ back as it was. Restored files get a new time stamp so that they are rebuilt.
restore() {
    local f
    for f in "$@"; do
        cp "$work/pristine/${f#"$tree/src/"}" "$f"
        touch "$f"
    done
}

start=$SECONDS
echo "mutate.sh: building the unmutated tree in $build"
buildIt "$logs/build-baseline.log" || { echo "mutate.sh: the unmutated tree does not build, see $logs/build-baseline.log" >&2; exit 1; }
if [ "$baseline" = 1 ]; then
    echo "mutate.sh: running the unmutated suite (every test must pass)"
    failed="$(runTests "$logs/baseline.xml" "$logs/baseline.log")"
    if [ -n "$failed" ]; then
        echo "mutate.sh: the unmutated suite fails, so no mutation can be scored:" >&2
        echo "$failed" | sed 's/^/  /' >&2
        exit 1
    fi
    echo "mutate.sh: baseline green: $(py count "$logs/baseline.xml") tests, $((SECONDS - start)) s"
fi

# ---- the mutations
report="$work/report.txt"
: >"$report"
killed=0 other=0 survived=0 broken=0
names() { echo "$1" | head -n 4 | paste -sd ' ' -; } # the first few failing tests
row() { printf '%-20s %-19s %s\n' "$1" "$2" "$3" | tee -a "$report"; }
row "mutation" "outcome" "failing tests"
for id in "${ids[@]}"; do
    t0=$SECONDS
    fileText="$(py apply "$list" "$tree/src" "$id")" || exit 1
    mapfile -t files <<<"$fileText"
    if ! buildIt "$logs/build-$id.log"; then
        restore "${files[@]}"
        row "$id" "DOES NOT BUILD" "see $logs/build-$id.log"
        broken=$((broken + 1))
        continue
    fi
    regex="$(py field "$list" "$id" regex)"
    if [ "$(ctest --test-dir "$build" -N -R "$regex" | grep -c 'Test *#' || true)" = 0 ]; then
        restore "${files[@]}"
        echo "mutate.sh: mutation '$id': its tests ($(py field "$list" "$id" tests)) match no test" >&2
        exit 1
    fi
    behaviour="$(runTests "$logs/$id-behaviour.xml" "$logs/$id-behaviour.log" -R "$regex")"
    rest=""
    if [ -z "$behaviour" ] || [ "$full" = 1 ]; then
        rest="$(runTests "$logs/$id-rest.xml" "$logs/$id-rest.log" -E "$regex")"
    fi
    restore "${files[@]}"
    if [ -n "$behaviour" ]; then
        killed=$((killed + 1))
        row "$id" "killed (behaviour)" "$(names "$behaviour")"
    elif [ -n "$rest" ]; then
        other=$((other + 1))
        row "$id" "killed (other)" "$(names "$rest")"
    else
        survived=$((survived + 1))
        row "$id" "SURVIVED" "-"
    fi
    echo "    ($((SECONDS - t0)) s; $(py field "$list" "$id" what))"
done

total=$((killed + other + survived))
{
    echo
    echo "killed by a behaviour test: $killed of $total ($(awk -v k="$killed" -v t="$total" 'BEGIN { printf "%.1f", t ? 100 * k / t : 0 }') %)"
    echo "killed only by other tests: $other; survived: $survived"
    [ "$broken" -gt 0 ] && echo "did not build (not scored; fix the list): $broken"
    echo "time: $(( (SECONDS - start) / 60 )) min; logs in $logs"
} | tee -a "$report"
[ "$broken" -eq 0 ]
