#!/usr/bin/env bash
# The Record tab driven as an operator would, with real key presses: a `quick`
# session on the simulated rig is opened in the real window under Xvfb, then xdotool presses
# Space (pre-flight), Space (first trial), R (redo it), Space (again), Space (second trial), N with
# a typed note and Enter, and Ctrl+Q. Afterwards the session folder must say: every trial accepted, the redone attempt kept
# under superseded/, and the journal holds the redo. Each step waits for the journal, not a clock.
set -eu
lmc=${1:?usage: record_keyboard_e2e.sh LMC LMC_WORKBENCH WORK_DIR}
workbench=${2:?}
work=${3:?}
rm -rf "$work"; mkdir -p "$work"
session="$work/session"
"$lmc" session new --subject E2E --protocol quick -o "$session" > "$work/new.log"

cat > "$work/drive.sh" <<'EOF'
#!/usr/bin/env bash
set -eu
workbench=$1; session=$2; work=$3
# shellcheck source=tests/smoke/xdotool_lib.sh
source "$4"  # press, start
pid=""
trap '[ -z "$pid" ] || kill "$pid" 2>/dev/null || true' EXIT
journal="$session/journal.jsonl"

# Waits (up to 60 s) until the journal holds `count` lines matching `pattern`.
wait_for() {
  local pattern=$1 count=$2 what=$3
  for _ in $(seq 600); do
    if [ "$(grep -c -- "$pattern" "$journal" || true)" -ge "$count" ]; then return 0; fi
    if ! kill -0 $pid 2>/dev/null; then echo "the workbench exited while waiting for $what"; cat "$work/workbench.log"; exit 1; fi
    sleep 0.1
  done
  echo "timed out waiting for $what; journal:"; cat "$journal"; exit 1
}

LMC_STATUS_TRACE="$work/status-trace.txt" start --session "$session" --fast
wait_for '"session_opened"' 1 "the session to open"
sleep 1  # a few frames for the tab to draw
press space; wait_for '"type":"preflight"' 1 "the pre-flight"
sleep 0.5
press space; wait_for '"type":"trial_accepted"' 1 "the first trial"
sleep 0.5
press r; wait_for '"type":"trial_redone"' 1 "the redo"
# The status bar says what the redo did (a failed earlier action's red line used to stay).
for _ in $(seq 50); do grep -q "is recorded again next" "$work/status-trace.txt" && break; sleep 0.1; done
grep -q "is recorded again next" "$work/status-trace.txt" || { echo "the status bar did not follow the redo"; cat "$work/status-trace.txt"; exit 1; }
sleep 0.5
press space; wait_for '"type":"trial_accepted"' 2 "the first trial, again"
sleep 0.5
press space; wait_for '"type":"trial_accepted"' 3 "the second trial"
sleep 0.5
# No pause after N: letters typed before the field has the keyboard must still reach the note.
press n
xdotool type --delay 30 "glove slipped"
press Return; wait_for '"text":"glove slipped"' 1 "the note"
sleep 0.5
press ctrl+q
for _ in $(seq 100); do kill -0 $pid 2>/dev/null || break; sleep 0.1; done
if kill -0 $pid 2>/dev/null; then echo "Ctrl+Q did not close the workbench"; exit 1; fi
trap - EXIT
EOF
chmod +x "$work/drive.sh"
xvfb-run -a -s "-screen 0 1280x800x24" "$work/drive.sh" "$workbench" "$session" "$work" \
  "$(cd "$(dirname "$0")" && pwd)/xdotool_lib.sh"

"$lmc" session status "$session" --json > "$work/status.json"
python3 - "$work/status.json" "$session" <<'EOF'
import json, os, sys
status = json.load(open(sys.argv[1]))
session = sys.argv[2]
trials = status["trials"]
assert [t["status"] for t in trials] == ["accepted", "accepted"], [t["status"] for t in trials]
assert trials[0]["attempts"] == 2 and trials[1]["attempts"] == 1, [t["attempts"] for t in trials]
first = trials[0]["attempt_history"][0]["files"]
assert first.startswith("superseded/"), first
kept = os.path.join(session, first, "LMC_Naiv_Static101.raw.txt")
assert os.path.getsize(kept) > 0, kept
assert os.path.exists(os.path.join(session, "LMC_Naiv_Static101.raw.txt"))
assert os.path.exists(os.path.join(session, "LMC_Naiv_Index101.raw.txt"))
notes = [json.loads(l) for l in open(os.path.join(session, "journal.jsonl")) if '"type":"note"' in l]
assert [n["text"] for n in notes] == ["glove slipped"], notes
print("record tab e2e: 2 trials accepted by keyboard, 1 redo kept under", first, "and a note typed after N")
EOF
