#!/bin/sh
# Issue 13 goal 1, the rip of a sustained pull, by direction and resolution: the `pull` scene (6 m
# sheet, top edge pinned, a 0.3 m hand at the bottom centre moving at 0.5 m/s along pull.angle, 0 =
# straight down, 90 = sideways) for 4 s, headless. Per run: tears, the first tear's time, the rip's
# principal axis (the tear events' rest positions; degrees from horizontal, so the axis across a
# pull at angle a is a), its length along that axis, the pieces and the smallest piece.
# Usage, from the repository root:
#   sh bench/gestures/pull_rips.sh [path/to/clothtear] [angles] [resolutions] [hand speeds] [seconds]
#   e.g. sh bench/gestures/pull_rips.sh build/release/src/app/clothtear "0 30 60 90" "40 80 160"
# A rip's length moves with the round-off (one run can be 1.6 m and the next, 1e-4 m/s faster, 3.1 m):
# compare resolutions over several hand speeds a little apart, e.g. "0.4999 0.5 0.5001", not one run.
# With more than one speed a summary per angle and resolution follows the runs: the median length and
# axis, and how many runs left each number of pieces.
# More options for the runner: EXTRA for every run, EXTRA_<res> for one resolution's runs, e.g.
#   EXTRA_40="--set time.substeps=7" EXTRA_160="--set tear.weak_threshold=0.2" sh bench/gestures/pull_rips.sh ...
set -eu
BIN=${1:-build/release/src/app/clothtear}
ANGLES=${2:-0 30 60 90}
RES=${3:-40 80 160}
SPEEDS=${4:-0.5}
SECONDS_RUN=${5:-4}
ROWS=$(mktemp)
RUN=$(mktemp)
trap 'rm -f "$ROWS" "$RUN"' EXIT
echo "angle   res  speed  tears  first (s)  axis (deg)  length (m)  pieces  smallest (m^2)"
for a in $ANGLES; do
    for n in $RES; do
      for v in $SPEEDS; do
        # shellcheck disable=SC2086 # the extra options are words
        "$BIN" --headless --scene pull --seconds "$SECONDS_RUN" --set pull.angle="$a" --set pull.speed="$v" \
            --set cloth.resolution_x="$n" --set cloth.resolution_y="$n" ${EXTRA:-} $(eval "echo \${EXTRA_$n:-}") \
            --json "$RUN" >/dev/null || { echo "pull_rips.sh: the run at $a deg, $n a side, $v m/s failed (above)" >&2; exit 1; }
        python3 -c '
import json, math, sys
a, n, v = sys.argv[1], sys.argv[2], sys.argv[3]
r = json.load(open(sys.argv[4]))
ev = r["tear_events"]
pieces = r["pieces"]
if not ev:
    print(f"{a:>5} {n:>5} {v:>6} {0:6d}"); sys.exit()
xs = [e["rest"][0] for e in ev]; ys = [e["rest"][1] for e in ev]
mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
sxx = sum((x - mx) ** 2 for x in xs); syy = sum((y - my) ** 2 for y in ys)
sxy = sum((x - mx) * (y - my) for x, y in zip(xs, ys))
th = 0.5 * math.atan2(2 * sxy, sxx - syy)
p = [(x - mx) * math.cos(th) + (y - my) * math.sin(th) for x, y in zip(xs, ys)]
first, count, smallest = ev[0]["time"], pieces["count"], pieces["smallest_area"]
print(f"{a:>5} {n:>5} {v:>6} {len(ev):6d} {first:10.2f} {math.degrees(th):11.1f} {max(p) - min(p):11.2f} {count:7d} {smallest:15.3f}")
' "$a" "$n" "$v" "$RUN" | tee -a "$ROWS"
      done
    done
done
[ "$(echo $SPEEDS | wc -w)" -gt 1 ] || exit 0
python3 - "$ROWS" <<'PY'
import collections, statistics, sys
runs = collections.defaultdict(list)
for line in open(sys.argv[1]):
    f = line.split()
    runs[(int(f[0]), int(f[1]))].append(f)
print("angle   res  runs  median length (m)  median axis (deg)  runs by pieces")
for (a, n), rows in sorted(runs.items()):
    torn = [r for r in rows if len(r) > 4]
    length = statistics.median(float(r[6]) for r in torn) if torn else 0.0
    axis = statistics.median(float(r[5]) for r in torn) if torn else 0.0
    pieces = collections.Counter(int(r[7]) if len(r) > 4 else 1 for r in rows)
    by = ", ".join(f"{k}: {pieces[k]}" for k in sorted(pieces))
    print(f"{a:>5} {n:>5} {len(rows):5d} {length:18.2f} {axis:18.1f}  {by}")
PY
