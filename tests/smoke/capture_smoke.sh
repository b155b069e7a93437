#!/usr/bin/env bash
# Renders workbench tabs under Xvfb and checks each PNG: present, window-sized, not one colour.
# Usage: capture_smoke.sh LMC_WORKBENCH OUT_DIR [TAB…] (all tabs when none are named).
set -eu
bin=${1:?usage: capture_smoke.sh LMC_WORKBENCH OUT_DIR [TAB…]}
out=${2:?}
shift 2
tabs=()
for t in "$@"; do tabs+=(--tab "$t"); done
rm -rf "$out"; mkdir -p "$out"
xvfb-run -a -s "-screen 0 1280x800x24" "$bin" --capture "$out" "${tabs[@]}"
python3 "$(dirname "$0")/check_png.py" "$out" 1280 800
