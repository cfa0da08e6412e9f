#!/bin/sh
# Every gesture here, and the README's drag, on the default curtain at 40, 80 and 160 particles a
# side in the real window (Xvfb + Mesa): tears, pieces and the smallest piece in rest triangles of
# the mesh (issue 13, no confetti: none under five). Usage, from the repository root:
#   sh bench/gestures/run.sh [path/to/clothtear]
set -eu
BIN=${1:-build/release/src/app/clothtear}
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
for script in bench/gestures/*.txt assets/screenshots/drag.txt; do
    for n in 40 80 160; do
        name=$(basename "$script" .txt)
        SDL_AUDIODRIVER=dummy xvfb-run -a -s "-screen 0 1280x720x24" "$BIN" --scene curtain \
            --set cloth.resolution_x=$n --set cloth.resolution_y=$n --script "$script" \
            --json "$OUT/$name-$n.json" >/dev/null 2>&1
        python3 - "$OUT/$name-$n.json" "$name" "$n" <<'PY'
import json, sys
report = json.load(open(sys.argv[1]))
n = int(sys.argv[3])
pieces = report["pieces"]
# The curtain is 2 m x 2 m: a rest triangle of an n x n grid is 4 / (2 (n - 1)^2) m^2.
triangle = 4.0 / (2 * (n - 1) ** 2)
small = sum(1 for a in pieces["areas"] if a < 5 * triangle)
print(f"{sys.argv[2]:16s} {n:4d}  tears {report['tears_total']:4d}  pieces {pieces['count']}  "
      f"smallest {pieces['smallest_area'] / triangle:9.1f} rest triangles  under 5: {small}")
PY
    done
done
