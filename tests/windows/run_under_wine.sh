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
# Wine's prefix lives in build/windows/wineprefix (made on the first run, about 15 s).
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$PWD
build=$root/build/windows
[ "${1:-}" = --no-build ] || scripts/build-windows --tests

export WINEPREFIX=${WINEPREFIX:-$build/wineprefix} WINEDEBUG=-all
# No Mono or Gecko download prompts: nothing here needs .NET or a browser engine.
export WINEDLLOVERRIDES="mscoree,mshtml="
wine=$(command -v wine64 || true)
[ -n "$wine" ] || wine=/usr/lib/wine/wine64
[ -x "$wine" ] || { echo "run_under_wine: wine64 is missing (scripts/install-deps --windows)" >&2; exit 1; }
winepath() { "$wine" winepath.exe -w "$1" 2>/dev/null | tr -d '\r'; }
step_start=$SECONDS
step() {
  echo "run_under_wine: $* (+$((SECONDS - step_start)) s)"
}
if [ ! -f "$WINEPREFIX/system.reg" ]; then
  step "making the Wine prefix $WINEPREFIX"
  "$wine" wineboot.exe -i >/dev/null 2>&1
fi

status=0
logs=$build/wine-logs
rm -rf "$logs" && mkdir -p "$logs"
for suite in lmc_core_tests lmc_devices_tests lmc_app_tests lmc_leapc_tests; do
  exe=$build/tests/$suite.exe
  [ -f "$exe" ] || { echo "run_under_wine: $exe was not built" >&2; status=1; continue; }
  start=$SECONDS
  if "$wine" "$exe" --gtest_brief=1 >"$logs/$suite.log" 2>&1; then result=passed; else result=FAILED; status=1; fi
  summary=$(grep -E '^\[  (PASSED|FAILED|SKIPPED) ' "$logs/$suite.log" | tr -d '\r' | tr '\n' ' ')
  step "$suite under Wine: $result in $((SECONDS - start)) s: $summary"
  [ "$result" = passed ] || grep -E '^\[  FAILED  \]' "$logs/$suite.log" | head -20
done

# The end-to-end run, given Windows paths (drive letter, backslashes, a space, an umlaut).
e2e=$build/e2e
rm -rf "$e2e" && mkdir -p "$e2e"
study_unix="$e2e/Dr Müller study"
mkdir -p "$study_unix"
study=$(winepath "$study_unix")
lmc_exe() { "$wine" "$build/app/lmc.exe" "$@"; }
start=$SECONDS
export LMC_CACHE_DIR="$e2e/cache"
lmc_exe session new --subject S01 --protocol study --seconds 1 --hand-length-mm 180 --hand-breadth-mm 82 \
  --operator Operator -o "$study\\S01" >"$logs/e2e-new.log" 2>&1
lmc_exe session run "$study\\S01" --backend sim --fast --auto --quiet --seed 5 >"$logs/e2e-run.log" 2>&1
lmc_exe process "$study\\S01" --method reference -q -o "$(winepath "$e2e")\\processed" >"$logs/e2e-process.log" 2>&1
lmc_exe export bids "$study" -o "$(winepath "$e2e")\\bids" >"$logs/e2e-export.log" 2>&1
step "lmc.exe session new, run (study protocol, simulated), process, export bids: $((SECONDS - start)) s"
[ -f "$study_unix/S01/session.json" ] && [ -d "$e2e/bids" ] ||
  { echo "run_under_wine: the end-to-end session left no session.json or no dataset (logs in $logs)" >&2; status=1; }

# A name the ANSI code page cannot carry (Windows-1252 has no Ł) is refused by name, and nothing is
# written under the look-alike ("Lukasz") the code page would have made of it.
odd_unix="$e2e/Dr Łukasz study"
mkdir -p "$odd_unix"
if lmc_exe session new --subject S02 --protocol quick --seconds 1 --hand-length-mm 180 --hand-breadth-mm 82 \
  -o "$(winepath "$odd_unix")\\S02" >"$logs/e2e-refused.log" 2>&1; then
  echo "run_under_wine: lmc.exe took a folder name its code page changes" >&2
  status=1
elif grep -q "would reach this program changed" "$logs/e2e-refused.log" && [ ! -e "$e2e/Dr Lukasz study" ] &&
  [ -z "$(ls -A "$odd_unix")" ]; then
  step "a folder name outside the code page (Łukasz) refused by name, nothing written"
else
  echo "run_under_wine: the refused name was not said, or something was written:" >&2
  cat "$logs/e2e-refused.log" >&2
  status=1
fi

# A killed lmc.exe (TerminateProcess: Wine's process is ended by SIGKILL) mid-trial, then resumed:
# the journal and the rows written stay, the cut trial is marked interrupted and recorded again.
drill="$e2e/drill"
drill_win=$(winepath "$drill")
lmc_exe session new --subject K01 --protocol quick --seconds 4 --hand-length-mm 180 --hand-breadth-mm 82 \
  -o "$drill_win" >"$logs/drill-new.log" 2>&1
"$wine" "$build/app/lmc.exe" session run "$drill_win" --backend sim --auto --quiet --countdown 0 --seed 5 \
  >"$logs/drill-run1.log" 2>&1 &
victim=$!
for _ in $(seq 300); do
  grep -q '"trial_started"' "$drill/journal.jsonl" 2>/dev/null && break
  sleep 0.1
done
sleep 1
kill -9 "$victim" 2>/dev/null || true
wait "$victim" 2>/dev/null || true
if lmc_exe session run "$drill_win" --backend sim --fast --auto --quiet --seed 5 >"$logs/drill-run2.log" 2>&1 &&
  grep -q '"trial_interrupted"' "$drill/journal.jsonl" &&
  [ "$(grep -c '"trial_accepted"' "$drill/journal.jsonl")" -ge 2 ]; then
  step "killed lmc.exe mid-trial, resumed: the trial was marked interrupted and both trials were recorded"
else
  echo "run_under_wine: the killed-and-resumed session did not complete; journal:" >&2
  cat "$drill/journal.jsonl" >&2
  status=1
fi

validator=$(scripts/tools-dir bids-validator)
if "$validator" --version >/dev/null 2>&1; then
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
linux_lmc=${LMC_LINUX_LMC:-}
for candidate in "$root/build/check/app/lmc" "$root/build/release/app/lmc"; do
  [ -n "$linux_lmc" ] || { [ -x "$candidate" ] && linux_lmc=$candidate; }
done
if [ -n "$linux_lmc" ]; then
  linux=$build/e2e-linux
  rm -rf "$linux" && mkdir -p "$linux/Dr Müller study"
  LMC_CACHE_DIR="$linux/cache" "$linux_lmc" session new --subject S01 --protocol study --seconds 1 --hand-length-mm 180 \
    --hand-breadth-mm 82 --operator Operator -o "$linux/Dr Müller study/S01" >/dev/null
  LMC_CACHE_DIR="$linux/cache" "$linux_lmc" session run "$linux/Dr Müller study/S01" --backend sim --fast --auto --quiet \
    --seed 5 >/dev/null
  LMC_CACHE_DIR="$linux/cache" "$linux_lmc" process "$linux/Dr Müller study/S01" --method reference -q -o "$linux/processed" >/dev/null
  LMC_CACHE_DIR="$linux/cache" "$linux_lmc" export bids "$linux/Dr Müller study" -o "$linux/bids" >/dev/null
  python3 tests/windows/compare_outputs.py "$linux" "$e2e" || status=1
else
  echo "run_under_wine: no Linux lmc built (build/check or build/release, or LMC_LINUX_LMC): byte comparison skipped"
fi
step "done, status $status"
exit $status
