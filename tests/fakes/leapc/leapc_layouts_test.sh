#!/usr/bin/env bash
# The real `lmc` finds LeapC wherever Ultraleap's packages put it: the test double (a shared
# library named as Ultraleap's) is installed at each layout in a scratch root
# (LMC_LEAPC_SEARCH_ROOT), and `lmc devices --backend leapc` must load it from there, say so with
# its version, and list the double's controllers. With nothing installed it must fail and list
# every place tried; a named library is used as named; a major version the backend was not
# written for, and a library that is not LeapC, are refused with the reason.
set -u
lmc=${1:?usage: leapc_layouts_test.sh LMC FAKE_LIBLEAPC}
fake=${2:?usage: leapc_layouts_test.sh LMC FAKE_LIBLEAPC}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
unset LMC_LEAPC_LIBRARY
export LMC_FAKE_LEAPC_DEVICES="3:LP11111,7:LP22222"
status=0
fail() { echo "FAIL: $*"; status=1; }

# layout name, path under the root, version the double reports
check_layout() {
  local name=$1 path=$2 version=$3 root="$scratch/$1" out
  mkdir -p "$root$(dirname "$path")"
  cp "$fake" "$root$path"
  out=$(LMC_LEAPC_SEARCH_ROOT="$root" LMC_FAKE_LEAPC_VERSION="$version" \
        "$lmc" devices --backend leapc --wait 0.3 2>&1) || { fail "$name: lmc exited non-zero: $out"; return; }
  grep -qF "LeapC $version from $root$path" <<<"$out" || fail "$name: library not reported as loaded from $root$path: $out"
  grep -qF "Ultraleap service $version" <<<"$out" || fail "$name: service version not reported: $out"
  grep -q "LP11111" <<<"$out" && grep -q "LP22222" <<<"$out" || fail "$name: controllers not listed: $out"
  echo "ok: $name ($path)"
}
check_layout gemini-5.6-deb /usr/lib/ultraleap-hand-tracking-service/libLeapC.so.5 5.6.1
check_layout gemini-5.6-deb-sdk /usr/share/doc/ultraleap-hand-tracking-service/lib/libLeapC.so.5 5.6.3
check_layout gemini-5.17-deb /usr/lib/x86_64-linux-gnu/libLeapC.so.5 5.17.1
check_layout hyperion-6-deb /usr/lib/x86_64-linux-gnu/libLeapC.so.6 6.1.0
check_layout client-7-sdk-tarball /opt/ultraleap/LeapSDK/lib/libLeapC.so 7.4.0
check_layout sdk-tarball /opt/ultraleap/LeapSDK/lib/libLeapC.so.5 5.6.1

# Nothing installed: non-zero, every place tried and why.
empty="$scratch/empty"; mkdir -p "$empty"
if out=$(LMC_LEAPC_SEARCH_ROOT="$empty" "$lmc" devices --backend leapc --wait 0.3 2>&1); then
  fail "nothing installed: lmc exited 0: $out"
fi
for p in /usr/lib/x86_64-linux-gnu/libLeapC.so.6 /usr/lib/ultraleap-hand-tracking-service/libLeapC.so.5 \
         /usr/lib/x86_64-linux-gnu/libLeapC.so.5 /opt/ultraleap/LeapSDK/lib/libLeapC.so.5; do
  grep -qF "$empty$p [" <<<"$out" || fail "nothing installed: $p not in the list: $out"
done
grep -q "not there" <<<"$out" || fail "nothing installed: no reason given: $out"
echo "ok: nothing installed"

# Named with --leapc-library: used as named, whatever the known places hold.
out=$(LMC_LEAPC_SEARCH_ROOT="$empty" "$lmc" devices --backend leapc --wait 0.3 --leapc-library "$fake" 2>&1) ||
  fail "--leapc-library: lmc exited non-zero: $out"
grep -qF "from $fake (--leapc-library)" <<<"$out" || fail "--leapc-library not used: $out"
echo "ok: --leapc-library"

# A LeapC 8 where Hyperion goes is refused with its version; the Gemini one behind it is loaded.
root="$scratch/mixed"
mkdir -p "$root/usr/lib/x86_64-linux-gnu" "$root/opt/ultraleap/LeapSDK/lib"
cp "$fake" "$root/usr/lib/x86_64-linux-gnu/libLeapC.so.6"
out=$(LMC_LEAPC_SEARCH_ROOT="$root" LMC_FAKE_LEAPC_VERSION=8.0.0 "$lmc" devices --backend leapc --wait 0.3 2>&1) &&
  fail "LeapC 8 only: lmc exited 0: $out"
grep -q "refused: it is LeapC 8.0.0" <<<"$out" || fail "LeapC 8 not refused with its version: $out"
# Not LeapC at all (another library under its name): refused for the functions it lacks.
other=$(ldd "$lmc" | awk '/libm\.so/ {print $3; exit}')
if [ -n "$other" ]; then
  cp "$other" "$root/opt/ultraleap/LeapSDK/lib/libLeapC.so.5"
  out=$(LMC_LEAPC_SEARCH_ROOT="$root" LMC_FAKE_LEAPC_VERSION=8.0.0 "$lmc" devices --backend leapc --wait 0.3 2>&1)
  grep -q "refused: it lacks LeapCreateConnection" <<<"$out" || fail "a library that is not LeapC was not refused: $out"
fi
echo "ok: refusals"
exit $status
