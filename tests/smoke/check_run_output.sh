#!/usr/bin/env bash
# What a newcomer sees after `scripts/run` with no display, checked the way they would look at it
# (.ci/run calls this right after scripts/run): both demo subjects recorded in full, a picture of
# every tab, none blank or of the wrong size, and the Review tab showing the demo's trials.
# Usage: check_run_output.sh LMC DEMO_DIR SCREENSHOT_DIR STATUS_TRACE
set -euo pipefail
lmc=${1:?usage: check_run_output.sh LMC DEMO_DIR SCREENSHOT_DIR STATUS_TRACE}
demo=${2:?}
shots=${3:?}
trace=${4:?}
fail() {
  echo "check_run_output: FAILED: $*" >&2
  exit 1
}
for subject in S01 S02; do
  status=$("$lmc" session status "$demo/$subject" 2>&1) || fail "lmc session status $demo/$subject: $status"
  grep -q '16 of 16 trials accepted' <<<"$status" ||
    fail "the demo session $demo/$subject is not complete: $(head -n 3 <<<"$status")"
done
for tab in layout devices record review; do
  compgen -G "$shots/$tab*.png" >/dev/null || fail "no picture of the $tab tab in $shots"
done
python3 "$(dirname "$0")/check_png.py" "$shots" 1280 800 --min-content 0.03 ||
  fail "a picture in $shots is blank or of the wrong size (above)"
[ -s "$trace" ] || fail "the workbench wrote no status line to $trace"
grep -Eq 'Review: ([1-9][0-9]*) trial' "$trace" ||
  fail "the Review tab never said it had the demo's trials (status lines: $trace)"
echo "check_run_output: the demo's two subjects are complete, every tab was rendered ($(compgen -G "$shots/*.png" | wc -l) pictures), Review read the demo"
