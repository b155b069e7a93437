#!/usr/bin/env bash
# A whole subject session driven in the real window as an operator would (xdotool under Xvfb, real
# time, the simulated rig): a new `quick` session with the subject screen open (F2), the pre-flight,
# the first trial, a note, Close, Ctrl+Q; the session reopened with --session, its second trial
# killed with SIGKILL mid-trial; reopened again: the resume, the trial recorded again, Close, Ctrl+Q;
# then the Review tab opening the session and exporting it as BIDS then a trial as C3D (into its own
# folder, not the dataset), and in the Layout tab an optimiser search started and
# cancelled (its best-so-far layout is evaluated, never shown as zeros); then a careless operator in a
# 1024x700 window (the same subject id twice, Enter after Esc in the countdown, Ctrl+Q while
# recording). Every workbench must end with exit code 0 (Close after a
# trial used to end the program with std::out_of_range), and the subject screen must show the red
# circle from go for the trial's whole length (the countdown used to eat the recording: the subject
# saw "3, 2, 1" and never the circle). Steps wait for the journal, never a fixed clock.
set -eu
lmc=${1:?usage: record_session_e2e.sh LMC LMC_WORKBENCH WORK_DIR}
workbench=${2:?}
work=${3:?}
rm -rf "$work"; mkdir -p "$work"
session="$work/session"
"$lmc" session new --subject E2F --protocol quick -o "$session" > "$work/new.log"

cat > "$work/drive.sh" <<'DRIVE'
#!/usr/bin/env bash
set -eu
workbench=$1; session=$2; work=$3
# shellcheck source=tests/smoke/xdotool_lib.sh
source "$4"
journal="$session/journal.jsonl"
export LMC_SUBJECT_TRACE="$work/subject-trace.txt" LMC_STATUS_TRACE="$work/status-trace.txt"
pid=""
# Waits (up to 60 s) until the journal holds `count` lines matching `pattern`.
wait_for() {
  local pattern=$1 count=$2 what=$3
  for _ in $(seq 600); do
    if [ "$(grep -c -- "$pattern" "$journal" || true)" -ge "$count" ]; then return 0; fi
    if ! kill -0 "$pid" 2>/dev/null; then echo "the workbench exited while waiting for $what"; cat "$work/workbench.log"; exit 1; fi
    sleep 0.1
  done
  shot timed-out
  echo "timed out waiting for $what; journal:"; cat "$journal"
  echo "status lines:"; cat "$work/status-trace.txt" 2>/dev/null || true
  echo "subject screen:"; tail -40 "$work/subject-trace.txt" 2>/dev/null || true
  exit 1
}
# The keyboard back to the operator's window, and a moment for the focus events to settle (a key
# pressed while the window gains focus can be dropped).
focus_main() {
  xdotool windowactivate --sync "$window" 2>/dev/null || xdotool windowfocus --sync "$window" || true
  sleep 0.5
}
# Ctrl+Q and the exit code the operator would see.
quit() {
  press ctrl+q
  local status=0
  wait "$pid" || status=$?
  if [ "$status" -ne 0 ]; then echo "the workbench ended with exit code $status ($1)"; cat "$work/workbench.log"; exit 1; fi
}
# The Close button at the right end of the Record tab's header line.
click_close() {
  click 1215 52
  wait_for_status "closed; everything recorded is kept" "the session to close"
}

# 1. A new session: subject screen, pre-flight, the first trial, a note, Close, Ctrl+Q.
start --session "$session"
wait_for '"session_opened"' 1 "the session to open"
sleep 0.5
press F2
sleep 1
focus_main
press space; wait_for '"type":"preflight"' 1 "the pre-flight"
sleep 0.5
press space; wait_for '"type":"trial_accepted"' 1 "the first trial"
sleep 0.5
press F2  # the subject screen closes; it may cover the operator's window on one monitor
sleep 0.5
focus_main
press n
# The note field takes the keyboard a frame or two after N; on a loaded machine (the suite, a
# build beside it) that can be a second. A person sees the line open before typing; so does this.
sleep 1
xdotool type --delay 30 "cuff loose"
press Return; wait_for '"text":"cuff loose"' 1 "the note"
sleep 0.5
click_close
sleep 1
kill -0 "$pid" 2>/dev/null || { echo "Close after a recorded trial ended the workbench"; cat "$work/workbench.log"; exit 1; }
quit "after Close"

# 2. Reopened; the second trial is killed with SIGKILL two seconds after it starts.
start --session "$session"
wait_for '"session_opened"' 2 "the session to reopen"
sleep 0.5
press space; wait_for '"type":"preflight"' 2 "the second pre-flight"
sleep 0.5
press space; wait_for '"type":"trial_started"' 2 "the second trial to start"
# Mid-trial: a second after the subject screen's circle came on (after the countdown).
for _ in $(seq 300); do [ "$(grep -c ' recording 1 ' "$LMC_SUBJECT_TRACE")" -ge 2 ] && break; sleep 0.1; done
sleep 1
kill -9 "$pid"
wait "$pid" 2>/dev/null || true

# 3. Resumed: the cut trial is recorded again, then Close and Ctrl+Q.
start --session "$session"
wait_for '"session_opened"' 3 "the resume"
sleep 0.5
press F2
sleep 1
focus_main
press space; wait_for '"type":"preflight"' 3 "the pre-flight after the resume"
sleep 0.5
press space; wait_for '"type":"trial_accepted"' 2 "the second trial, recorded again"
sleep 0.5
press F2
sleep 0.5
focus_main
grep -c "closed; everything recorded is kept" "$work/status-trace.txt" | grep -q 1  # the first Close's line
click 1215 52
for _ in $(seq 100); do [ "$(grep -c "closed; everything recorded is kept" "$work/status-trace.txt")" -ge 2 ] && break; sleep 0.1; done
sleep 1
kill -0 "$pid" 2>/dev/null || { echo "Close after the resumed trial ended the workbench"; cat "$work/workbench.log"; exit 1; }
quit "after the resume"

# 4. The Review tab opens the session: both trials processed into the test's own cache. Then
# Export...: the session as a BIDS dataset, and after it the selected trial as C3D, which must land
# in the per-trial exports' own folder, never in the dataset. Exports default under the sessions
# folder: the test's own.
export LMC_CACHE_DIR="$work/cache" LMC_SESSIONS_DIR="$work"
start --tab review --review "$session"
for _ in $(seq 600); do
  [ "$(find "$work/cache" -name '*.json' 2>/dev/null | wc -l)" -ge 2 ] && break
  kill -0 "$pid" 2>/dev/null || { echo "the workbench exited while Review processed"; cat "$work/workbench.log"; exit 1; }
  sleep 0.1
done
[ "$(find "$work/cache" -name '*.json' | wc -l)" -ge 2 ] || { echo "Review did not process the session"; exit 1; }
wait_for_status "trial(s) ready" "Review's count of the trials"
# A click lost on a loaded machine is made again (a click that lands changes nothing the second time).
exported() { grep -q -- "exported $1 trial(s) to $work/exports/$2" "$work/status-trace.txt"; }
for _ in $(seq 15); do
  click 296 55    # Export... (its window opens in the middle of the 1280x800 window)
  sleep 1
  click 308 280   # The opened folders as a BIDS-motion dataset
  sleep 0.5
  click 357 424   # Export (under the BIDS options)
  for _ in $(seq 30); do exported 2 bids-dataset && break 2; sleep 0.1; done
done
wait_for_status "exported 2 trial(s) to $work/exports/bids-dataset" "the BIDS export"
for _ in $(seq 15); do
  click 308 234   # The selected trial
  sleep 0.5
  click 357 400   # Export, as C3D
  for _ in $(seq 30); do exported 1 trials-c3d && break 2; sleep 0.1; done
done
wait_for_status "exported 1 trial(s) to $work/exports/trials-c3d" "the C3D export after the BIDS export"
ls "$work"/exports/trials-c3d/*.c3d > /dev/null || { echo "no C3D file in $work/exports/trials-c3d"; exit 1; }
if find "$work/exports/bids-dataset" -name '*.c3d' | grep .; then echo "the C3D export landed in the BIDS dataset"; exit 1; fi
sleep 0.5
quit "in Review"

# 5. The Layout tab: Optimiser, Start, Cancel after a few seconds; the status bar reads the
# best-so-far layout's own figures.
# Clicks at x y until the status bar has shown `pattern` (up to 2 min): Start stays disabled until
# the pose set is ready, which takes much longer on a loaded machine.
click_until_status() {
  for _ in $(seq 60); do
    click "$1" "$2"
    for _ in $(seq 20); do
      grep -q -- "$3" "$work/status-trace.txt" && return 0
      sleep 0.1
    done
  done
  shot timed-out
  echo "timed out waiting for: $4; status lines:"; cat "$work/status-trace.txt"; exit 1
}
start
sleep 2
click 985 87     # the Optimiser panel's tab
sleep 1
click_until_status 880 448 "Optimiser started" "the search to start"    # Start optimiser
sleep 3
click_until_status 1240 425 "Optimiser cancelled" "the search to stop"  # Cancel, at the end of the progress row
sleep 0.5
quit "after the optimiser was cancelled"

# 6. The careless operator, in a 1024x700 window (a laptop with a taskbar), one monitor: the same
# subject id again (the question; A adds a second session of E2F), Esc in the countdown then Enter
# (nothing to keep: refused, naming why), R, Space, Ctrl+Q while recording (asks; Enter keeps
# recording), Ctrl+Q again and S (stop, keep, quit: exit 0).
# LMC_SESSIONS_DIR is $work since step 4: the first session, $work/session (subject E2F), lies under it.
start --tab record --size 1024 --height 700
sleep 2
click 135 100     # the subject id field of the set-up form: "S01" out, "E2F" in
sleep 0.5
# One key a frame or so: a key pressed and released within one frame of the check build can be lost.
for k in End BackSpace BackSpace BackSpace BackSpace; do press $k; sleep 0.3; done
xdotool type --delay 80 "E2F"
sleep 0.5
click 155 446     # Create session and go to pre-flight: E2F is already recorded, so it asks
sleep 1
press a           # Add a second session of E2F
for _ in $(seq 100); do second=$(ls -d "$work"/E2F-* 2>/dev/null | head -1); [ -n "$second" ] && break; sleep 0.1; done
[ -n "$second" ] || { echo "no second session of E2F was made"; cat "$work/status-trace.txt"; exit 1; }
journal="$second/journal.jsonl"
press space; wait_for '"type":"preflight"' 1 "the second session's pre-flight"
sleep 0.5
countdowns=$(grep -c ' countdown ' "$LMC_SUBJECT_TRACE" || true)
press space
for _ in $(seq 300); do [ "$(grep -c ' countdown ' "$LMC_SUBJECT_TRACE")" -gt "$countdowns" ] && break; sleep 0.05; done
press Escape; wait_for '"type":"trial_stopped"' 1 "Esc in the countdown"
sleep 0.5
press Return; wait_for_status "cannot be accepted: 0 frames: aborted before go — no data" "Enter on an empty attempt"
press r; wait_for_status "is recorded again next" "the redo"
sleep 0.5
circles=$(grep -c ' recording 1 ' "$LMC_SUBJECT_TRACE" || true)
press space
for _ in $(seq 300); do [ "$(grep -c ' recording 1 ' "$LMC_SUBJECT_TRACE")" -gt "$circles" ] && break; sleep 0.05; done
press ctrl+q
sleep 1.5
kill -0 "$pid" 2>/dev/null || { echo "Ctrl+Q while recording quit at once"; exit 1; }
press Return      # the question's default: keep recording
sleep 0.5
kill -0 "$pid" 2>/dev/null || { echo "Enter on the quit question quit"; exit 1; }
[ "$(grep -c '"type":"trial_stopped"' "$journal")" -eq 1 ] || { echo "the trial stopped though recording was kept"; cat "$journal"; exit 1; }
press ctrl+q
sleep 0.5
press s           # stop it, keep it, quit
status=0
wait "$pid" || status=$?
[ "$status" -eq 0 ] || { echo "stop-and-quit ended with exit code $status"; cat "$work/workbench.log"; exit 1; }
echo "$second" > "$work/second-session.txt"
DRIVE
chmod +x "$work/drive.sh"
xvfb-run -a -s "-screen 0 1280x800x24" "$work/drive.sh" "$workbench" "$session" "$work" "$(cd "$(dirname "$0")" && pwd)/xdotool_lib.sh"

"$lmc" session status "$session" --json > "$work/status.json"
python3 - "$work/status.json" "$session" "$work/subject-trace.txt" "$work/status-trace.txt" <<'CHECK'
import json, os, re, sys
status = json.load(open(sys.argv[1]))
session, trace_file, status_file = sys.argv[2], sys.argv[3], sys.argv[4]
trials = status["trials"]
assert [t["status"] for t in trials] == ["accepted", "accepted"], [t["status"] for t in trials]
assert trials[1]["attempts"] == 2, trials[1]["attempts"]  # the one killed, kept aside, and the one that finished
journal = [json.loads(l) for l in open(os.path.join(session, "journal.jsonl"))]
notes = [e["text"] for e in journal if e["type"] == "note"]
assert notes == ["cuff loose"], notes
stopped = [e for e in journal if e["type"] == "trial_stopped"]
assert all(e.get("go_utc") for e in stopped), stopped
# The subject screen's stages: every completed trial showed the red circle from go for its 3 s
# (the screen reads the trial's progress about ten times a second, so the last value it saw may
# be up to a snapshot short of 3 s).
lines = [l.split() for l in open(trace_file)]
circles = []
for k, (t, stage, circle, _) in enumerate(lines):
    if circle == "1" and k + 1 < len(lines):
        t_end, _, _, reached = lines[k + 1]
        circles.append((float(t_end) - float(t), float(reached)))
full = [c for c in circles if c[1] >= 2.7]
assert len(full) >= 2, ("the circle was not shown for two whole trials", circles)
for shown_s, reached_s in full:
    assert shown_s >= 2.6, ("the circle was shown for only", shown_s, "s")
# Close said what it did, twice; the cancelled search's figures are its own, not zeros.
shown = open(status_file).read().splitlines()
assert sum("closed; everything recorded is kept" in l for l in shown) == 2, shown
cancelled = [l for l in shown if "Optimiser cancelled" in l]
assert cancelled, shown
m = re.search(r"best R = ([0-9.]+) \(M ([0-9.]+)\)", cancelled[-1])
assert m and float(m.group(1)) > 0 and float(m.group(2)) > 0, cancelled[-1]
countdowns = [l for l in lines if l[1] == "countdown"]
assert len(countdowns) >= 2, "the subject saw no countdown"
# The careless operator's session: a second session of E2F; its first trial aborted in the
# countdown (no frames, never kept), recorded again and stopped by quitting: kept, not accepted.
second = open(os.path.join(os.path.dirname(trace_file), "second-session.txt")).read().strip()
second_journal = [json.loads(l) for l in open(os.path.join(second, "journal.jsonl"))]
assert second_journal[0]["setup"]["subject"]["id"] == "E2F", second_journal[0]
assert not [e for e in second_journal if e["type"] == "trial_accepted"], "a failed or empty attempt was accepted"
second_stops = [e for e in second_journal if e["type"] == "trial_stopped"]
assert [e["outcome"] for e in second_stops] == ["aborted", "interrupted"], second_stops
assert not second_stops[0].get("go_utc"), second_stops[0]
verdicts = [e for e in second_journal if e["type"] == "trial_verdict"]
assert verdicts and verdicts[0]["quality"]["reasons"] == ["aborted before go — no data"], verdicts[:1]
assert not os.path.exists(os.path.join(second, ".lock")), "the lock stayed after a clean quit"
print("record session e2e: 2 trials accepted in the window, the circle shown %s, Close and Ctrl+Q exit 0, "
      "SIGKILL mid-trial resumed, Review processed the session, %s"
      % (", ".join("%.1f s" % c[0] for c in full), cancelled[-1].split("\t")[1]))
CHECK
