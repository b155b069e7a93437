#!/usr/bin/env bash
# The Review tab on a processed simulated session: a quick subject session is recorded
# on the simulated rig, opened with --review, and the pictures (the trial against Vicon, the
# agreement view, the study tables, Export… before and after exporting the trials shown as C3D) are
# checked: present, window-sized, not one colour, at 1280x800 and 1024x700 with no text cut
# (--check-text); the export wrote one C3D per trial. The
# processing cache goes to the test's own folder, never the user's.
set -eu -o pipefail
lmc=${1:?usage: review_capture.sh LMC LMC_WORKBENCH OUT_DIR}
bin=${2:?}
out=${3:?}
rm -rf "$out"; mkdir -p "$out"
"$lmc" session new --subject S01 --protocol quick -o "$out/S01" >/dev/null
"$lmc" session run "$out/S01" --backend sim --fast --auto --quiet --seed 4 >/dev/null
export LMC_CACHE_DIR="$out/cache"
mkdir -p "$out/png"
LMC_REVIEW_PNG="$out/png/bland-altman.png" LMC_REVIEW_EXPORT_DIR="$out/export" \
  xvfb-run -a -s "-screen 0 1280x800x24" "$bin" --capture "$out/shots" --also-size 1024x700 --check-text --tab review --review "$out/S01" | tee "$out/capture.log"
grep -q "review.png" "$out/capture.log"
grep -q "review-agreement.png" "$out/capture.log"
grep -q "review-study-tables.png" "$out/capture.log"
grep -q "review-export.png" "$out/capture.log"
grep -q "review-export-done.png" "$out/capture.log"
test "$(find "$out/export" -name '*.c3d' | wc -l)" -eq 2
python3 "$(dirname "$0")/check_png.py" "$out/shots" 1280 800
# The PNG export: a Bland-Altman figure rendered off screen at 1000 x 700.
python3 "$(dirname "$0")/check_png.py" "$out/png" 1000 700
# Both trials were processed into the cache, and nothing was written into the session.
test "$(find "$out/cache" -name '*.json' | wc -l)" -eq 2
if find "$out/S01" -name '*.summary.json' | grep -q .; then echo "processing wrote into the session folder" >&2; exit 1; fi
