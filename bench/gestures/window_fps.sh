#!/bin/sh
# Issue 15 goal 5: the window's frame rate while the README's drag tears the curtain (the first 70
# frames of assets/screenshots/tear.txt, in which the hand tears) and with the same curtain paused
# (drawing alone), at each resolution, under Xvfb + Mesa llvmpipe. Prints app.fps and the means of
# the steps and of the buffer swap (ms a frame) from the app's JSON report. Run it on an idle machine.
# Usage, from the repository root:
#   sh bench/gestures/window_fps.sh [path/to/clothtear] [resolutions]
#   e.g. sh bench/gestures/window_fps.sh build/release/src/app/clothtear "64 80 100 128"
set -eu
BIN=${1:-build/release/src/app/clothtear}
RES=${2:-64 80 100 128}
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
printf '0 key P\n150 end\n' > "$OUT/paused.txt"
echo "  res  case      fps  steps (ms)  swap (ms)"
for n in $RES; do
    for case in tearing paused; do
        if [ "$case" = tearing ]; then args="--script assets/screenshots/tear.txt --frames 70"; else args="--script $OUT/paused.txt"; fi
        # shellcheck disable=SC2086 # the arguments are words
        SDL_AUDIODRIVER=dummy xvfb-run -a -s "-screen 0 1280x720x24" "$BIN" --scene curtain \
            --set cloth.resolution_x="$n" --set cloth.resolution_y="$n" $args --json "$OUT/r.json" >/dev/null 2>&1 ||
            { echo "window_fps.sh: the $case run at $n a side failed" >&2; exit 1; }
        python3 - "$OUT/r.json" "$n" "$case" <<'PY'
import json, sys
app = json.load(open(sys.argv[1]))["app"]
mean = app["mean"]
print(f"{sys.argv[2]:>5}  {sys.argv[3]:8s} {app['fps']:5.1f}  {mean['steps_ms']:10.1f}  {mean['swap_ms']:9.1f}")
PY
    done
done
