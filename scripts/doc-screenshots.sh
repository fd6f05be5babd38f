#!/usr/bin/env bash
# doc-screenshots.sh - takes the screenshots under docs/ again, on lavapipe (the viewer's under
# Xvfb at 1280x720), from build/idview, so that they show today's default model and panel.
# Needs the packages scripts/setup.sh test installs (xvfb, occt-misc) and build/lavapipe-25.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
idview=$root/build/idview
icd=$root/build/lavapipe-25/lvp_icd.json
export VK_ICD_FILENAMES=$icd VK_DRIVER_FILES=$icd
export LD_LIBRARY_PATH=$root/build/lavapipe-25/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
occ=/usr/share/opencascade/data
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Nothing of the user's, and nothing kept from one viewer session to the next: no saved
# viewer settings, no caches.
export XDG_CONFIG_HOME=$work/config XDG_CACHE_HOME=$work/cache
docs=$root/docs

# Headless, with the commands the pages give.
"$idview" --headless --size 960x540 --pick 430,250 --pick 5,5 --select 600,340 \
    --screenshot "$docs/pick-lavapipe.png" >/dev/null
"$idview" --headless --model "$occ/step/linkrods.step" --edges --part-weight 0.7 \
    --size 960x540 --pick 480,265 --screenshot "$docs/cad-step-lavapipe.png" >/dev/null

# viewer OUT.png SCRIPT-LINES [FLAGS...]: the viewer under Xvfb runs the script, whose last
# step saves the presented image (panel included) as OUT.png.
viewer() {
    local out=$1 lines=$2
    shift 2
    printf '%s\n' "$lines" "9.0 screenshot $docs/$out" "9.5 quit" >"$work/script.txt"
    xvfb-run -a -s "-screen 0 1280x800x24" "$idview" --size 1280x720 --no-saved-settings --script "$work/script.txt" \
        "$@" >/dev/null
}

# The default model, fitted beside the panel, the floor plate selected and the gearbox
# housing hovered.
viewer viewer.png "0.5 key F
1.5 frames 3
2.0 click 640 300
2.5 move 975 395
3.0 frames 8"
# Edges, a box over the rear wheel and the floor, a part hovered.
viewer edges-box-lavapipe.png "0.5 key F
1.5 frames 3
2.0 key E
2.5 box 470 260 640 420
3.0 move 975 395
3.5 frames 8"
# Motor-c.brep cut open, edges, and a measurement (the script docs/viewer.md shows).
viewer section-measure-lavapipe.png "0.6 key E
0.7 key M
0.8 click 810 560
0.9 frames 6
1.0 click 700 300
1.1 frames 6" --model "$occ/occ/Motor-c.brep" --section y,-20,flip
echo "doc-screenshots: docs/{pick,cad-step,edges-box,section-measure}-lavapipe.png, docs/viewer.png"
