#!/usr/bin/env bash
# Review → Layout driven in the real window as a researcher would (xdotool under Xvfb): a quick
# simulated session opened in Review, "Design a layout for these trials" pressed, and the Layout tab
# must come up with those trials as its pose set (the status bar says how many recorded frames, the
# Optimiser panel lists where they came from). The screen is saved before and after when xwd and
# netpbm are there (WORK_DIR/review.png, WORK_DIR/layout.png). Ctrl+Q must end with exit code 0.
# Usage: review_to_layout_e2e.sh LMC LMC_WORKBENCH WORK_DIR (it starts its own Xvfb without a display).
set -eu
if [ -z "${DISPLAY:-}" ]; then exec xvfb-run -a -s "-screen 0 1280x800x24" "$0" "$@"; fi
lmc=${1:?usage: review_to_layout_e2e.sh LMC LMC_WORKBENCH WORK_DIR}
workbench=${2:?}
work=${3:?}
rm -rf "$work"; mkdir -p "$work"
session="$work/session"
"$lmc" session new --subject R2L --protocol quick -o "$session" > "$work/new.log"
"$lmc" session run "$session" --backend sim --fast --auto --quiet --seed 4 > "$work/run.log"
export LMC_STATUS_TRACE="$work/status-trace.txt" LMC_CACHE_DIR="$work/cache"

# shellcheck source=tests/smoke/xdotool_lib.sh
source "$(dirname "$0")/xdotool_lib.sh"

start --tab review --review "$session"
wait_for_status "trial(s) ready" "Review to process the session" 1200
sleep 1
shot review
# "Design a layout for these trials", in Review's top bar after Export...
click 457 55
wait_for_status "Layout: designing for 2 trial(s)" "the button to hand the trials to the Layout tab" 1200
wait_for_status "recorded frames" "the Layout tab to read the trials as its pose set" 1200
sleep 1
click 985 87  # the Optimiser panel's tab: the pose set and where it came from
sleep 1.5
shot layout
# The pose set is part of the layout document (one undo step): undo it, so Ctrl+Q has nothing to ask.
xdotool key --clearmodifiers ctrl+z
wait_for_status "Undid Change pose set" "the pose set change to be undone" 1200
# On a loaded machine a key pressed while a frame takes long can be missed: press again until it ends.
for _ in $(seq 20); do
  xdotool key --clearmodifiers ctrl+q
  for _ in $(seq 30); do kill -0 "$pid" 2>/dev/null || break 2; sleep 0.1; done
done
status=0
wait "$pid" || status=$?
[ "$status" -eq 0 ] || { echo "the workbench ended with exit code $status"; cat "$work/workbench.log"; exit 1; }
grep "recorded frames" "$work/status-trace.txt"
