#!/bin/sh
# Regenerates the README screenshots in assets/screenshots with the app itself, under Xvfb, from the
# input scripts next to them. Usage: tools/make_screenshots.sh [path/to/clothtear]
set -e
cd "$(dirname "$0")/.."
app=${1:-build/release/src/app/clothtear}
export SDL_AUDIODRIVER=${SDL_AUDIODRIVER:-dummy} # the scripts tear: no sound while making pictures
dir=assets/screenshots
shotWith() { # name script scene [extra args]
    name=$1 script=$2 scene=$3
    shift 3
    xvfb-run -a -s "-screen 0 1280x720x24" "$app" --scene "$scene" --script "$dir/$script.txt" \
        --screenshot "$dir/$name.png" "$@"
}
shot() { # name scene [extra args]: the script of the same name
    name=$1
    shift
    shotWith "$name" "$name" "$@"
}
shot first curtain
shot tear curtain
shot ball curtain
shot strain curtain
shot help flag
# Rewind and undo (issue 14): a ball torn through and the timeline dragged back; the same throw undone.
shot rewind curtain
shot undo curtain
# The knife (hotkey 6) drawn down through the corners scene: two halves, each on its own pin.
shot knife corners
# Piece deletion: the same cut, the stats pane's pieces list opened, one half's Delete clicked.
shot delete corners
# Save and load: the pull scene torn by the headless runner and saved, loaded in the window.
world=$(mktemp /tmp/clothtear-pulled-XXXXXX.ctw)
"$app" --headless --scene pull --seconds 4 --save "$world" >/dev/null
xvfb-run -a -s "-screen 0 1280x720x24" "$app" --load "$world" --script "$dir/load.txt" --screenshot "$dir/load.png"
rm -f "$world"
# Torn pieces sleep: the curtain cut across, its strip asleep on the ground after 5.8 s, picked up.
world=$(mktemp /tmp/clothtear-cut-XXXXXX.ctw)
"$app" --headless --scene curtain --seconds 5.8 --cut '0.02:-1.2,-0.4;1.2,-0.4' --save "$world" >/dev/null
xvfb-run -a -s "-screen 0 1280x720x24" "$app" --load "$world" --script "$dir/pickup.txt" --screenshot "$dir/pickup.png"
rm -f "$world"
# Torn edges (issue 15, goal 4): the rip of tear.txt seen from behind; the drop scene's cloth on the
# ground. torn-before.png and drop-before.png were made once by the renderer before goal 4 (commit
# 5854b26) from the same scripts; they are not regenerated.
shot torn curtain
shot drop drop
# One drag at three resolutions (issue 13: the same gesture, the same kind of rip).
for n in 40 80 160; do
    shotWith "drag$n" drag curtain --set cloth.resolution_x=$n --set cloth.resolution_y=$n
done
# The pull scene torn sideways for 5 s at three resolutions (issue 13 goal 1: the rip as long in metres).
for n in 40 80 160; do
    xvfb-run -a -s "-screen 0 1280x720x24" "$app" --scene pull --set pull.angle=90 --set cloth.resolution_x=$n \
        --set cloth.resolution_y=$n --frames 300 --screenshot "$dir/pull$n.png"
done
