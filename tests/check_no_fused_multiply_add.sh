#!/bin/sh
# The visibility kernel's three builds (baseline, AVX2, AVX-512) must give bit-identical results,
# so none of them may fuse a multiply and an add into one rounding (visibility_kernel.cpp); nor may
# the AVX2 forms of the palm hull and the fusion's sums, which must equal their plain forms. The
# compiler is told so (-ffp-contract=off); this checks the program it made: no FMA instruction in
# any build of those entry points. Each function is found in the symbol table (address and size)
# and only it is disassembled: the whole program would take objdump seconds.
# Usage: check_no_fused_multiply_add.sh PROGRAM
set -eu
program=$1
ranges=$(nm -C -S --defined-only "$program" |
  awk '$3 ~ /^[tT]$/ && /(device_run|visible_fingers|six_point_candidates|accumulate_lanes)/ {print $1, $2}')
functions=$(printf '%s\n' "$ranges" | grep -c . || true)
if [ "$functions" -lt 8 ]; then
  echo "expected the kernel's entry points (device_run_*, visible_fingers_*, six_point_candidates_*, accumulate_lanes_*) in $program, found $functions" >&2
  exit 1
fi
listing=$(printf '%s\n' "$ranges" | while read -r start size; do
  objdump -d -C --no-show-raw-insn --start-address="0x$start" \
    --stop-address="$(printf '0x%x' $((0x$start + 0x$size)))" "$program" | sed -n '/>:$/,$p'
done)
if printf '%s\n' "$listing" | grep -E '\svf(n)?m(add|sub)[0-9]{3}' >/dev/null; then
  echo "fused multiply-add in the checked functions of $program:" >&2
  printf '%s\n' "$listing" | grep -E '>:$|\svf(n)?m(add|sub)[0-9]{3}' | head -20 >&2
  exit 1
fi
echo "no fused multiply-add in $functions checked functions of $program"
