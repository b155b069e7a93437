#!/usr/bin/env bash
# Renders workbench tabs under Xvfb at a UI scale (--ui-scale, as a 150 % screen would ask for) and
# checks each PNG as capture_smoke.sh does: the 1280 x 800 layout in 1280 x 800 times the scale
# pixels, not blank, and no text cut (--check-text reads the frame in the layout's own units).
# Usage: capture_at_ui_scale.sh LMC_WORKBENCH OUT_DIR SCALE [TAB…] (all tabs when none are named).
set -eu
bin=${1:?usage: capture_at_ui_scale.sh LMC_WORKBENCH OUT_DIR SCALE [TAB…]}
out=${2:?}
scale=${3:?}
shift 3
tabs=()
for t in "$@"; do tabs+=(--tab "$t"); done
width=$(python3 -c "print(round(1280 * $scale))")
height=$(python3 -c "print(round(800 * $scale))")
rm -rf "$out"; mkdir -p "$out"
xvfb-run -a -s "-screen 0 ${width}x${height}x24" "$bin" --capture "$out" --ui-scale "$scale" --check-text "${tabs[@]}"
python3 "$(dirname "$0")/check_png.py" "$out" "$width" "$height"
