#!/usr/bin/env bash
# Renders every workbench tab under Xvfb and checks each PNG: present, window-sized, not one colour.
set -eu
bin=${1:?usage: capture_smoke.sh LMC_WORKBENCH OUT_DIR}
out=${2:?}
rm -rf "$out"; mkdir -p "$out"
xvfb-run -a -s "-screen 0 1280x800x24" "$bin" --capture "$out"
python3 "$(dirname "$0")/check_png.py" "$out" 1280 800
