#!/usr/bin/env bash
# The Windows workbench driven as an operator would (xdotool under Xvfb, Wine, real time, the
# simulated rig), unpacked from the zip: the Record tab's form with the `quick` protocol, Create,
# Space (pre-flight), Space (the first trial, accepted when it ends), Close, Ctrl+Q. The program
# must end with exit code 0 and the trial be on disk. Steps wait for the journal or the status
# line (LMC_STATUS_TRACE), never a fixed clock, so a loaded machine slows it without failing it.
#
#   tests/windows/workbench_drive_under_wine.sh [BUILD_DIR [OUT_DIR]]
#
# BUILD_DIR: the Windows build (default build/windows, after scripts/build-windows); OUT_DIR: the
# session and logs (default BUILD_DIR/workbench-drive). Needs wine64, Xvfb, xdotool and unzip.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
# shellcheck source=tests/windows/workbench_wine_env.sh
source "$root/tests/windows/workbench_wine_env.sh" workbench-drive "$@"
new_prefix wineprefix-workbench-96 96
mkdir -p "$out/sessions" "$out/config"
# The test's own sessions folder and status trace, as Windows paths.
export LMC_SESSIONS_DIR LMC_STATUS_TRACE
LMC_SESSIONS_DIR=$(winepath "$out/sessions")
LMC_STATUS_TRACE=$(winepath "$out/status-trace.txt")
end_wine  # a Wine started without the display would not open a window on it

cat > "$out/drive.sh" <<'DRIVE'
#!/usr/bin/env bash
set -eu
work=$1; workbench=$2; app=$3
# shellcheck source=tests/smoke/xdotool_lib.sh
source "$4"
pid=""
# Waits (up to 2 min: Wine on a loaded machine) until FILE holds a line matching PATTERN.
wait_for_line() {
  local file=$1 pattern=$2 what=$3
  for _ in $(seq 1200); do
    grep -q -- "$pattern" "$file" 2>/dev/null && return 0
    kill -0 "$pid" 2>/dev/null || { echo "the workbench exited while waiting for: $what"; cat "$work/workbench.log"; exit 1; }
    sleep 0.1
  done
  shot timed-out
  echo "timed out waiting for: $what; status lines:"; cat "$work/status-trace.txt" 2>/dev/null || true; exit 1
}
focus_main() {
  xdotool windowactivate --sync "$window" 2>/dev/null || xdotool windowfocus --sync "$window" || true
  sleep 0.5
}

start "$app" --tab record
wait_for_line "$work/status-trace.txt" . "the first frame's status line"
sleep 3  # a few frames for the Record tab to lay out
focus_main
# The set-up form at 1280 x 800: Protocol, then "quick" (the second of the sorted protocols).
click 135 238
sleep 1.5
click 90 279
sleep 1.5
shot form
click 155 432     # Create session and go to pre-flight
wait_for_line "$work/status-trace.txt" "session created in" "the session to be created"
session_win=$(grep -o 'session created in .*' "$work/status-trace.txt" | head -1 | sed 's/^session created in //' | tr -d '\r')
echo "$session_win" > "$work/session-windows-path.txt"
session=$("$workbench" winepath.exe -u "$session_win" 2>/dev/null | tr -d '\r')
journal="$session/journal.jsonl"
echo "$session" > "$work/session-path.txt"
sleep 1
press space; wait_for_line "$journal" '"type":"preflight"' "the pre-flight"
sleep 1
press space; wait_for_line "$journal" '"type":"trial_accepted"' "the first trial"
sleep 1
shot after-trial
click 1215 52     # Close, at the right end of the session's header line
wait_for_line "$work/status-trace.txt" "closed; everything recorded is kept" "the session to close"
sleep 1
kill -0 "$pid" 2>/dev/null || { echo "Close after a recorded trial ended the workbench"; cat "$work/workbench.log"; exit 1; }
press ctrl+q
status=0
wait "$pid" || status=$?
[ "$status" -eq 0 ] || { echo "lmc-workbench.exe ended with exit code $status after Ctrl+Q"; cat "$work/workbench.log"; exit 1; }
DRIVE
chmod +x "$out/drive.sh"
status=0
# A screen larger than the window: Wine, as Windows, keeps a window with its title bar inside it.
bounded "$out/drive.log" lmc-workbench.exe "the drive" \
  xvfb-run -a -s "-screen 0 1400x900x24" "$out/drive.sh" "$out" "$wine" "$app" "$root/tests/smoke/xdotool_lib.sh" || status=$?
cat "$out/drive.log"
end_wine
[ "$status" -eq 0 ] || { echo "workbench_drive_under_wine: FAILED (the drive above; pictures and logs in $out)"; exit 1; }

session=$(cat "$out/session-path.txt")
python3 - "$session" <<'CHECK'
import json, os, sys
session = sys.argv[1]
journal = [json.loads(l) for l in open(os.path.join(session, "journal.jsonl"), encoding="utf-8")]
created = journal[0]
assert created["type"] == "session_created", created
protocol = created["setup"]["protocol"]["name"]
assert protocol == "quick", "the session was made with the %s protocol, not quick (the form's dropdown)" % protocol
accepted = [e for e in journal if e["type"] == "trial_accepted"]
assert len(accepted) == 1, [e["type"] for e in journal]
trial = os.path.join(session, "LMC_Naiv_Static101.raw.txt")
assert os.path.getsize(trial) > 0, trial
assert not os.path.exists(os.path.join(session, ".lock")), "the session's lock stayed after Close and Ctrl+Q"
print("workbench_drive_under_wine: a quick session made in the window, one trial accepted (%d bytes), "
      "Close and Ctrl+Q with exit code 0: %s" % (os.path.getsize(trial), session))
CHECK
