# The operator's hands for the real-window tests (xdotool under Xvfb), sourced by them. They expect
# $work (the test's folder, with status-trace.txt written by LMC_STATUS_TRACE), and set or read $pid
# (the workbench's process) and $window (its X window).

press() { xdotool key --clearmodifiers "$1"; }

# A click held for a few frames (a press and release inside one frame can be missed), at window
# coordinates.
click() {
  xdotool mousemove --window "$window" "$1" "$2"
  sleep 0.2
  xdotool mousedown 1
  sleep 0.15
  xdotool mouseup 1
}

# The whole screen to $work/NAME.png, when xwd and netpbm or ImageMagick are there.
shot() {
  if command -v xwd >/dev/null && command -v xwdtopnm >/dev/null && command -v pnmtopng >/dev/null; then
    xwd -root -silent | xwdtopnm 2>/dev/null | pnmtopng > "$work/$1.png" && echo "screen: $work/$1.png"
  elif command -v import >/dev/null; then
    import -window root "$work/$1.png" && echo "screen: $work/$1.png"
  fi
}

# Waits until the status bar has shown a line matching PATTERN (up to TENTHS tenths of a second,
# 60 s by default); WHAT names the step in the failure message.
wait_for_status() {
  local pattern=$1 what=$2 tenths=${3:-600}
  for _ in $(seq "$tenths"); do
    grep -q -- "$pattern" "$work/status-trace.txt" 2>/dev/null && return 0
    kill -0 "$pid" 2>/dev/null || { echo "the workbench exited while waiting for: $what"; cat "$work/workbench.log"; exit 1; }
    sleep 0.1
  done
  shot timed-out
  echo "timed out waiting for: $what; status lines:"; cat "$work/status-trace.txt"; exit 1
}

# Starts the workbench with these arguments (its output to $work/workbench.log) and gives its
# window the keyboard.
start() {
  "$workbench" "$@" >> "$work/workbench.log" 2>&1 &
  pid=$!
  # Bounded: a workbench that never shows its window fails the test instead of holding it.
  window=$(timeout 120 xdotool search --sync --onlyvisible --name "LMC Workbench" | head -1 || true)
  [ -n "$window" ] || { echo "no window named LMC Workbench within 2 min; its output:"; cat "$work/workbench.log" 2>/dev/null; exit 1; }
  xdotool windowactivate --sync "$window" 2>/dev/null || xdotool windowfocus --sync "$window" || true
}
