# The Windows workbench as a lab unpacks it, under Wine, for the scripts beside this file, which
# source it with: DEFAULT_OUT_NAME [BUILD_DIR [OUT_DIR]] (BUILD_DIR: the Windows build holding
# lmc-workbench-windows-x64.zip, default build/windows; OUT_DIR: the test's own folder, emptied,
# default BUILD_DIR/DEFAULT_OUT_NAME). Expects $root (the checkout). Sets $build, $out, $wine,
# $app (the unpacked lmc-workbench.exe) and WINEPREFIX; gives winepath (a Linux path as Wine's
# Windows path), new_prefix NAME [DPI] and end_wine.
build=$(cd "${2:-$root/build/windows}" && pwd)
out=${3:-$build/$1}
rm -rf "$out" && mkdir -p "$out"
out=$(cd "$out" && pwd)
wine=$(command -v wine64 || true)
[ -n "$wine" ] || wine=/usr/lib/wine/wine64
[ -x "$wine" ] || { echo "workbench under Wine: wine64 is missing (scripts/install-deps --windows)" >&2; exit 1; }
wineserver=$(command -v wineserver || echo /usr/lib/wine/wineserver64)
export WINEDEBUG=-all
# No Mono or Gecko download prompts: nothing here needs .NET or a browser engine.
export WINEDLLOVERRIDES="mscoree,mshtml="

zip=$build/lmc-workbench-windows-x64.zip
[ -f "$zip" ] || { echo "workbench under Wine: $zip is missing (scripts/build-windows)" >&2; exit 1; }
rm -rf "$out/unpacked" && mkdir -p "$out/unpacked"
unzip -q "$zip" -d "$out/unpacked"
app=$out/unpacked/lmc-workbench/lmc-workbench.exe

winepath() { "$wine" winepath.exe -w "$1" 2>/dev/null | tr -d '\r'; }

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
  "$wineserver" -w
}

# Ends this prefix's Wine processes: its wineserver outlives the programs, and a program with a
# window started while a wineserver runs that began without the display (winepath, reg) fails
# ("Failed to create helper window").
end_wine() {
  "$wineserver" -k 2>/dev/null || true
  "$wineserver" -w 2>/dev/null || true
}
