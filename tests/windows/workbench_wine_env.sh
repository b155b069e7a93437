# The Windows workbench as a lab unpacks it, under Wine, for the scripts beside this file, which
# source it with: DEFAULT_OUT_NAME [BUILD_DIR [OUT_DIR]] (BUILD_DIR: the Windows build holding
# lmc-workbench-windows-x64.zip, default build/windows; OUT_DIR: the test's own folder, emptied,
# default BUILD_DIR/DEFAULT_OUT_NAME). Expects $root (the checkout). Sets $build, $out, $wine,
# $app (the unpacked lmc-workbench.exe) and WINEPREFIX; gives wine_env.sh's winepath, new_prefix
# NAME [DPI], end_wine and bounded.
build=$(cd "${2:-$root/build/windows}" && pwd)
out=${3:-$build/$1}
rm -rf "$out" && mkdir -p "$out"
out=$(cd "$out" && pwd)
# shellcheck source=tests/windows/wine_env.sh
source "$root/tests/windows/wine_env.sh"

zip=$build/lmc-workbench-windows-x64.zip
[ -f "$zip" ] || { echo "workbench under Wine: $zip is missing (scripts/build-windows)" >&2; exit 1; }
rm -rf "$out/unpacked" && mkdir -p "$out/unpacked"
unzip -q "$zip" -d "$out/unpacked"
app=$out/unpacked/lmc-workbench/lmc-workbench.exe

# new_prefix NAME [DPI]: a Wine prefix of the test's own in $out/NAME (kept in $build between runs:
# making one takes 15-60 s), set as WINEPREFIX; DPI (96 by default) is the screen's scaling as
# Windows' display settings set it (144 = 150 %).
new_prefix() {
  local name=$1 dpi=${2:-96}
  export WINEPREFIX=$build/$name
  if [ ! -f "$WINEPREFIX/system.reg" ]; then
    "$wine" wineboot.exe -i >/dev/null 2>&1
  fi
  local hex
  hex=$(printf '0x%x' "$dpi")
  # Where Windows keeps the scaling (and where Wine's winecfg writes it).
  "$wine" reg.exe add 'HKCU\Control Panel\Desktop' /v LogPixels /t REG_DWORD /d "$hex" /f >/dev/null 2>&1
  "$wine" reg.exe add 'HKCC\Software\Fonts' /v LogPixels /t REG_DWORD /d "$hex" /f >/dev/null 2>&1
  # A program that crashes must end, not wait for a person: Wine's crash dialog would keep it (and
  # the test) open for ever on a screen nobody sees; without it winedbg prints the backtrace.
  "$wine" reg.exe add 'HKCU\Software\Wine\WineDbg' /v ShowCrashDialog /t REG_DWORD /d 0 /f >/dev/null 2>&1
  end_wine
}

# Ends this prefix's Wine processes: its wineserver outlives the programs, and a program with a
# window started while a wineserver runs that began without the display (winepath, reg) fails
# ("Failed to create helper window"). Killed first, then waited for: a wait alone would last as
# long as any of the prefix's service processes chose to stay, and CI once ran out of time at a
# step like this one.
end_wine() {
  "$wineserver" -k 2>/dev/null || true
  timeout 60 "$wineserver" -w 2>/dev/null || echo "workbench under Wine: the wineserver of $WINEPREFIX outlived 60 s after its processes were killed" >&2
}

# A Wine step may not hang the test (nor CI, whose time is bounded): each runs under a limit, far
# above what it takes on a loaded machine (LMC_WINE_STEP_LIMIT seconds, 600 by default). Past it,
# the step fails saying so, with what Wine's debugger sees in the program's threads (to tell a
# deadlock from a wait for the display) and its log's end.
wine_step_limit=${LMC_WINE_STEP_LIMIT:-600}

# bounded LOG EXE WHAT COMMAND...: COMMAND (which runs EXE, a program of this prefix) with its
# output into LOG, under the limit; its exit code, or 124 past the limit: then the threads of EXE
# are reported, the prefix's processes ended (so COMMAND, xvfb-run say, ends and cleans up) and the
# log's end printed.
bounded() {
  local log=$1 exe=$2 what=$3
  shift 3
  "$@" >"$log" 2>&1 &
  local pid=$! waited=0 code=0
  while kill -0 "$pid" 2>/dev/null && [ "$waited" -lt "$wine_step_limit" ]; do
    sleep 1
    waited=$((waited + 1))
  done
  if kill -0 "$pid" 2>/dev/null; then
    echo "workbench under Wine: $what did not end within $wine_step_limit s (LMC_WINE_STEP_LIMIT)"
    thread_report "$exe" "$log.threads.txt"
    end_wine
    sleep 2
    kill "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
    echo "workbench under Wine: the end of $log:"
    tail -15 "$log" | sed 's/^/  | /'
    return 124
  fi
  wait "$pid" || code=$?
  return "$code"
}

# thread_report EXE FILE: while EXE runs in this prefix, every thread's backtrace as Wine's
# debugger sees it, the sections of EXE's process into FILE (the first lines printed).
thread_report() {
  local exe=$1 file=$2
  timeout 120 "$wine" winedbg.exe --command "bt all" 2>/dev/null | tr -d '\r' |
    awk -v exe="$exe" '/^Backtracing for thread/ { keep = index($0, exe) > 0 } keep' >"$file" || true
  if [ -s "$file" ]; then
    echo "workbench under Wine: the threads of $exe (all in $file):"
    head -60 "$file" | cut -c1-160 | sed 's/^/  | /'
  fi
}
