#!/usr/bin/env bash
# Renders workbench tabs under Xvfb at 1280x800 and again at 1024x700 (a laptop with a taskbar) and
# checks each PNG: present, window-sized, not one colour, and no text cut or drawn over other text
# (--check-text reads each frame's draw data; the list in OUT_DIR/cut-text.txt).
# Usage: capture_smoke.sh LMC_WORKBENCH OUT_DIR [TAB…] (all tabs when none are named).
set -eu
bin=${1:?usage: capture_smoke.sh LMC_WORKBENCH OUT_DIR [TAB…]}
out=${2:?}
shift 2
tabs=()
for t in "$@"; do tabs+=(--tab "$t"); done
rm -rf "$out"; mkdir -p "$out"
xvfb-run -a -s "-screen 0 1280x800x24" "$bin" --capture "$out" --also-size 1024x700 --check-text "${tabs[@]}"
python3 "$(dirname "$0")/check_png.py" "$out" 1280 800
