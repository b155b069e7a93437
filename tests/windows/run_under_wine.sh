#!/usr/bin/env bash
# The Windows leg: cross-builds the programs and the test suites (scripts/build-windows --tests),
# runs the suites under Wine, then uses lmc.exe as a lab would on a study session in a folder with a
# space, an umlaut and a drive letter: `session new`, `session run --backend sim --fast`, `process`,
# `export bids`. The official BIDS validator (scripts/install-deps --test-tools) must find no error
# in the Windows-written dataset, and the outputs are compared byte for byte with the Linux lmc's
# for the same seed (LMC_LINUX_LMC, else build/check or build/release; skipped, saying so, when
# neither is built). Headless: Wine needs no display for these programs.
#
#   tests/windows/run_under_wine.sh            everything above
#   tests/windows/run_under_wine.sh --no-build the binaries already in build/windows
#
# The suites (the app suite in two halves, GoogleTest's shards) and the end-to-end session run
# side by side, $LMC_WINE_JOBS at a time (default: one per core), as processes of one Wine prefix
# and so of one wineserver. The prefix is made once per machine, beside the cross-built libraries
# ($LMC_WINDOWS_DEPS_DIR/../wineprefix, about 15 s; WINEPREFIX to put it elsewhere): nothing in it
# belongs to one checkout, every file the tests write is under the checkout or the temporary folder.
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$PWD
build=$root/build/windows
[ "${1:-}" = --no-build ] || scripts/build-windows --tests

deps=${LMC_WINDOWS_DEPS_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/lmc-workbench/windows-deps}
export WINEPREFIX=${WINEPREFIX:-$(dirname "$deps")/wineprefix}
# shellcheck source=tests/windows/wine_env.sh
source "$root/tests/windows/wine_env.sh"
jobs=${LMC_WINE_JOBS:-$(nproc)}
# Against a hang only, never a verdict on speed: a suite takes under half a minute on an idle
# machine, and many times that when Wine is starved (its wineserver, through which every wait goes,
# at a low priority on a busy machine).
unit_limit=${LMC_WINE_UNIT_LIMIT:-600}
step_start=$SECONDS
step() {
  echo "run_under_wine: $* (+$((SECONDS - step_start)) s)"
}
if [ ! -f "$WINEPREFIX/system.reg" ]; then
  step "making the Wine prefix $WINEPREFIX"
  mkdir -p "$(dirname "$WINEPREFIX")"
  "$wine" wineboot.exe -i >/dev/null 2>&1
fi

status=0
logs=$build/wine-logs
rm -rf "$logs" && mkdir -p "$logs"

# suite NAME EXE [SHARD TOTAL]: one test binary (or one of its GoogleTest shards) under Wine; its
# output in $logs/NAME.log, its verdict line in $logs/NAME.result.
suite() {
  local name=$1 exe=$2 shard=${3:-0} total=${4:-1} start=$SECONDS result=passed
  if [ ! -f "$exe" ]; then
    echo "$exe was not built" >"$logs/$name.log"
    result=FAILED
  elif ! GTEST_SHARD_INDEX=$shard GTEST_TOTAL_SHARDS=$total timeout -k 10 "$unit_limit" "$wine" "$exe" --gtest_brief=1 \
    >"$logs/$name.log" 2>&1; then
    result=FAILED
  fi
  local summary
  summary=$(grep -E '^\[  (PASSED|FAILED|SKIPPED) ' "$logs/$name.log" | tr -d '\r' | tr '\n' ' ' || true)
  echo "$name under Wine: $result in $((SECONDS - start)) s: $summary" >"$logs/$name.result"
}

lmc_exe() { timeout -k 10 "$unit_limit" "$wine" "$build/app/lmc.exe" "$@"; }

# The end-to-end run, given Windows paths (drive letter, backslashes, a space, an umlaut).
e2e=$build/e2e
extra=$build/e2e-extra
end_to_end() {
  local start=$SECONDS ok=1
  rm -rf "$e2e" && mkdir -p "$e2e"
  local study_unix="$e2e/Dr Müller study"
  mkdir -p "$study_unix"
  local study
  study=$(winepath "$study_unix")
  export LMC_CACHE_DIR="$e2e/cache"
  lmc_exe session new --subject S01 --protocol study --seconds 1 --hand-length-mm 180 --hand-breadth-mm 82 \
    --operator Operator -o "$study\\S01" >"$logs/e2e-new.log" 2>&1 &&
    lmc_exe session run "$study\\S01" --backend sim --fast --auto --quiet --seed 5 >"$logs/e2e-run.log" 2>&1 &&
    lmc_exe process "$study\\S01" --method reference -q -o "$(winepath "$e2e")\\processed" >"$logs/e2e-process.log" 2>&1 &&
    lmc_exe export bids "$study" -o "$(winepath "$e2e")\\bids" >"$logs/e2e-export.log" 2>&1 || ok=0
  if [ "$ok" = 1 ] && [ -f "$study_unix/S01/session.json" ] && [ -d "$e2e/bids" ]; then
    echo "lmc.exe session new, run (study protocol, simulated), process, export bids: $((SECONDS - start)) s"
  else
    echo "FAILED: the end-to-end session stopped or left no session.json or no dataset (logs e2e-*.log in $logs)"
  fi

  # A name the ANSI code page cannot carry (Windows-1252 has no Ł) is refused by name, and nothing
  # is written under the look-alike ("Lukasz") the code page would have made of it.
  # Beside the study, not in it: the byte comparison reads every file under $e2e.
  rm -rf "$extra" && mkdir -p "$extra"
  local odd_unix="$extra/Dr Łukasz study"
  mkdir -p "$odd_unix"
  if lmc_exe session new --subject S02 --protocol quick --seconds 1 --hand-length-mm 180 --hand-breadth-mm 82 \
    -o "$(winepath "$odd_unix")\\S02" >"$logs/e2e-refused.log" 2>&1; then
    echo "FAILED: lmc.exe took a folder name its code page changes"
  elif grep -q "would reach this program changed" "$logs/e2e-refused.log" && [ ! -e "$extra/Dr Lukasz study" ] &&
    [ -z "$(ls -A "$odd_unix")" ]; then
    echo "a folder name outside the code page (Łukasz) refused by name, nothing written"
  else
    echo "FAILED: the refused name was not said, or something was written (e2e-refused.log)"
  fi

  # A killed lmc.exe (TerminateProcess: Wine's process is ended by SIGKILL) mid-trial, then
  # resumed: the journal and the rows written stay, the cut trial is marked interrupted and
  # recorded again. The kill comes once the trial's first rows are on disk, however slowly a
  # loaded machine gets there (the trial lasts 4 s in real time).
  local drill="$extra/drill" drill_win
  drill_win=$(winepath "$drill")
  lmc_exe session new --subject K01 --protocol quick --seconds 4 --hand-length-mm 180 --hand-breadth-mm 82 \
    -o "$drill_win" >"$logs/drill-new.log" 2>&1
  "$wine" "$build/app/lmc.exe" session run "$drill_win" --backend sim --auto --quiet --countdown 0 --seed 5 \
    >"$logs/drill-run1.log" 2>&1 &
  local victim=$! _
  for _ in $(seq 600); do
    grep -q '"trial_started"' "$drill/journal.jsonl" 2>/dev/null && break
    sleep 0.1
  done
  sleep 1
  kill -9 "$victim" 2>/dev/null || true
  wait "$victim" 2>/dev/null || true
  if lmc_exe session run "$drill_win" --backend sim --fast --auto --quiet --seed 5 >"$logs/drill-run2.log" 2>&1 &&
    grep -q '"trial_interrupted"' "$drill/journal.jsonl" &&
    [ "$(grep -c '"trial_accepted"' "$drill/journal.jsonl")" -ge 2 ]; then
    echo "killed lmc.exe mid-trial, resumed: the trial was marked interrupted and both trials were recorded"
  else
    echo "FAILED: the killed-and-resumed session did not complete; journal:"
    cat "$drill/journal.jsonl"
  fi
}

# The same session with the Linux lmc, same commands and seed, for the byte comparison.
linux=$build/e2e-linux
linux_lmc=${LMC_LINUX_LMC:-}
for candidate in "$root/build/check/app/lmc" "$root/build/release/app/lmc"; do
  [ -n "$linux_lmc" ] || { [ -x "$candidate" ] && linux_lmc=$candidate; }
done
linux_session() {
  rm -rf "$linux" && mkdir -p "$linux/Dr Müller study"
  local s="$linux/Dr Müller study/S01"
  export LMC_CACHE_DIR="$linux/cache"
  "$linux_lmc" session new --subject S01 --protocol study --seconds 1 --hand-length-mm 180 --hand-breadth-mm 82 \
    --operator Operator -o "$s" >/dev/null &&
    "$linux_lmc" session run "$s" --backend sim --fast --auto --quiet --seed 5 >/dev/null &&
    "$linux_lmc" process "$s" --method reference -q -o "$linux/processed" >/dev/null &&
    "$linux_lmc" export bids "$linux/Dr Müller study" -o "$linux/bids" >/dev/null &&
    echo "the Linux lmc's session for the comparison" || echo "FAILED: the Linux lmc's session ($linux_lmc)"
}

# The work, longest first, $jobs at a time; each unit's verdict lines go to $logs/NAME.result.
units=(app0 app1 e2e core devices leapc linux)
run_unit() {
  case "$1" in
    app0) suite lmc_app_tests-1of2 "$build/tests/lmc_app_tests.exe" 0 2 ;;
    app1) suite lmc_app_tests-2of2 "$build/tests/lmc_app_tests.exe" 1 2 ;;
    core) suite lmc_core_tests "$build/tests/lmc_core_tests.exe" ;;
    devices) suite lmc_devices_tests "$build/tests/lmc_devices_tests.exe" ;;
    leapc) suite lmc_leapc_tests "$build/tests/lmc_leapc_tests.exe" ;;
    e2e) end_to_end >"$logs/e2e.result" 2>&1 ;;
    linux)
      if [ -n "$linux_lmc" ]; then linux_session >"$logs/linux.result" 2>&1; else : >"$logs/linux.result"; fi
      ;;
  esac
}
for unit in "${units[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n || true; done
  run_unit "$unit" &
done
wait
for result in "$logs"/*.result; do
  while IFS= read -r line; do
    step "$line"
    case "$line" in
      *FAILED*) status=1 ;;
    esac
  done <"$result"
done
for log in "$logs"/lmc_*tests*.log; do
  grep -E '^\[  FAILED  \]' "$log" | tr -d '\r' | head -20 || true
done

validator=$(scripts/tools-dir bids-validator)
if [ ! -d "$e2e/bids" ]; then
  echo "run_under_wine: no dataset to validate" >&2
  status=1
elif "$validator" --version >/dev/null 2>&1; then
  "$validator" "$e2e/bids" --json >"$logs/bids.validator.json" 2>"$logs/bids.validator.err" || true
  if ! python3 - "$logs/bids.validator.json" <<'PY'; then status=1; fi
import json, sys
result = json.load(open(sys.argv[1]))
errors = result["issues"].get("errors", [])
warnings = result["issues"].get("warnings", [])
for e in errors:
    print(f"BIDS error {e['key']}: {e.get('reason', '')}", file=sys.stderr)
print(f"run_under_wine: the BIDS validator on the Windows-written dataset: {len(errors)} error(s), "
      f"{len(warnings)} warning(s) ({', '.join(sorted(w['key'] for w in warnings)) or 'none'})")
sys.exit(1 if errors else 0)
PY
else
  echo "run_under_wine: no BIDS validator at $validator (scripts/install-deps --test-tools)" >&2
  status=1
fi

# Byte for byte against the Linux lmc, same commands and seed.
if [ -z "$linux_lmc" ]; then
  echo "run_under_wine: no Linux lmc built (build/check or build/release, or LMC_LINUX_LMC): byte comparison skipped"
elif [ -d "$linux/bids" ]; then
  python3 tests/windows/compare_outputs.py "$linux" "$e2e" || status=1
else
  status=1
fi
step "done, status $status"
exit $status
