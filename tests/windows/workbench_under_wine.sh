#!/usr/bin/env bash
# The Windows workbench's window under Wine and Xvfb, as unpacked from the zip: `--capture` renders
# every tab, each picture checked as the Linux capture test checks them (tests/smoke/check_png.py:
# present, window-sized, not blank; --check-text: no text cut; the Review tab on a quick simulated
# session the zip's lmc.exe records first, as the demo is on Linux), and again with Windows' display
# scaling at 150 % (144 dpi): the same 1280 x 800 layout in 1920 x 1200 pixels, nothing cut. With
# LMC_LINUX_CAPTURE_DIR (a Linux `--capture` of the same build) the pictures must be the same set.
#
#   tests/windows/workbench_under_wine.sh [BUILD_DIR [OUT_DIR]]
#
# BUILD_DIR: the Windows build (default build/windows, after scripts/build-windows); OUT_DIR: the
# pictures (default BUILD_DIR/workbench-wine). Needs wine64, Xvfb (xvfb-run) and unzip.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
# shellcheck source=tests/windows/workbench_wine_env.sh
source "$root/tests/windows/workbench_wine_env.sh" workbench-wine "$@"
status=0
step_start=$SECONDS
step() { echo "workbench_under_wine: $* (+$((SECONDS - step_start)) s)"; }

# capture NAME DPI SCREEN ARGS...: every tab into $out/NAME under a prefix at DPI, on an Xvfb
# screen of SCREEN (WxH, larger than the window: Wine, as Windows, keeps a window with its title
# bar inside the screen and would shrink a window the screen's size); the workbench's own output
# in $out/NAME.log.
capture() {
  local name=$1 dpi=$2 screen=$3
  shift 3
  new_prefix "wineprefix-workbench-$dpi" "$dpi"
  mkdir -p "$out/$name" "$out/$name-sessions"
  local sessions pictures
  sessions=$(winepath "$out/$name-sessions")
  pictures=$(winepath "$out/$name")
  end_wine  # a Wine started without the display would not open a window on it
  # The Devices tab's calibration records into the sessions folder: the test's, not the user's.
  local code=0
  LMC_SESSIONS_DIR=$sessions LMC_LAYOUT_HEATMAP_CELLS=24 \
    bounded "$out/$name.log" lmc-workbench.exe "the capture at $dpi dpi" \
    xvfb-run -a -s "-screen 0 ${screen}x24" "$wine" "$app" --capture "$pictures" "$@" || code=$?
  if [ "$code" -ne 0 ]; then
    echo "lmc-workbench.exe --capture ended with $code (log: $out/$name.log)"
    tail -20 "$out/$name.log"
    status=1
  fi
  end_wine
}

# The demo data the Review tab's pictures show: a quick session on the simulated rig, recorded by
# the zip's lmc.exe.
new_prefix wineprefix-workbench-96 96
mkdir -p "$out/demo"
lmc_exe=$out/unpacked/lmc-workbench/lmc.exe
bounded "$out/demo-new.log" lmc.exe "lmc.exe session new" \
  "$wine" "$lmc_exe" session new --subject W01 --protocol quick --hand-length-mm 180 --hand-breadth-mm 82 \
  -o "$(winepath "$out/demo")\\W01" &&
  bounded "$out/demo.log" lmc.exe "lmc.exe session run" \
    "$wine" "$lmc_exe" session run "$(winepath "$out/demo")\\W01" --backend sim --fast --auto --quiet --seed 5 ||
  { echo "workbench_under_wine: lmc.exe could not record the demo session ($out/demo-new.log, $out/demo.log)"; status=1; }
demo=$(winepath "$out/demo")\\W01
end_wine
step "the demo session for the Review tab: $out/demo/W01"

capture capture 96 1400x900 --also-size 1024x700 --check-text --review "$demo"
python3 "$root/tests/smoke/check_png.py" "$out/capture" 1280 800 || status=1
for tab in layout devices record review; do
  [ -f "$out/capture/$tab.png" ] || { echo "workbench_under_wine: no picture of the $tab tab"; status=1; }
done
if [ -n "${LMC_LINUX_CAPTURE_DIR:-}" ]; then
  if diff <(cd "$LMC_LINUX_CAPTURE_DIR" && ls ./*.png) <(cd "$out/capture" && ls ./*.png); then
    step "the same $(ls "$out/capture"/*.png | wc -l) pictures as the Linux capture in $LMC_LINUX_CAPTURE_DIR"
  else
    echo "workbench_under_wine: the pictures differ from the Linux capture's (above: < Linux, > Wine)"
    status=1
  fi
fi
step "every tab at 96 dpi: $out/capture"

# 150 %: Windows tells the program (GLFW: the window's content scale), the workbench scales.
capture capture-144dpi 144 2100x1350 --check-text --review "$demo"
python3 "$root/tests/smoke/check_png.py" "$out/capture-144dpi" 1920 1200 || status=1
step "every tab at 144 dpi: $out/capture-144dpi"

[ "$status" -eq 0 ] && step "passed" || step "FAILED"
exit "$status"
