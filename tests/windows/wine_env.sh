# What every script under tests/windows needs of Wine, sourced by them: $wine (wine64; the script
# ends, saying so, when it is missing), $wineserver, a quiet Wine without download prompts, and
# winepath (a Linux path as Wine's Windows path).
wine=$(command -v wine64 || true)
[ -n "$wine" ] || wine=/usr/lib/wine/wine64
[ -x "$wine" ] || { echo "$(basename "$0"): wine64 is missing (scripts/install-deps --windows)" >&2; exit 1; }
wineserver=$(command -v wineserver || echo /usr/lib/wine/wineserver64)
export WINEDEBUG=-all
# No Mono or Gecko download prompts: nothing here needs .NET or a browser engine.
export WINEDLLOVERRIDES="mscoree,mshtml="

winepath() { "$wine" winepath.exe -w "$1" 2>/dev/null | tr -d '\r'; }
