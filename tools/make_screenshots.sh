#!/bin/sh
# Regenerates the README screenshots in assets/screenshots with the app itself, under Xvfb, from the
# input scripts next to them. Usage: tools/make_screenshots.sh [path/to/clothtear]
set -e
cd "$(dirname "$0")/.."
app=${1:-build/release/src/app/clothtear}
dir=assets/screenshots
shot() { # name scene [extra args]
    name=$1 scene=$2
    shift 2
    xvfb-run -a -s "-screen 0 1280x720x24" "$app" --scene "$scene" --script "$dir/$name.txt" \
        --screenshot "$dir/$name.png" "$@"
}
shot tear curtain
shot ball curtain --set ball.speed=7
shot strain curtain
shot help flag
