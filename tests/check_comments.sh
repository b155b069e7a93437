#!/usr/bin/env bash
# Fails, naming file and line, when a code comment carries a measurement's history instead of the
# lasting reason: a timing before → after ("36 → 30 ns"), a speed-up ("3 times faster", "18 % less
# CPU"), a share a profile once showed ("was a third of processing") or a date. Figures belong in
# docs/results/ (with the data and the command that give them), history in git. A comment whose
# figure or date is a contract (a format's own example, say) says so with the marker
# "contract-figure" on the same line.
set -u
root=${1:?usage: check_comments.sh SOURCE_DIR}
cd "$root" || exit 2
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  files=$(git ls-files -- core devices ui app tests cmake CMakeLists.txt)
else
  files=$(find core devices ui app tests cmake CMakeLists.txt -type f 2>/dev/null)
fi
# The comment of each line: C++ // and block-comment lines; CMake and shell # lines.
cxx=$(printf '%s\n' $files | grep -E '\.(h|hpp|cpp|cc|c)$')
hash=$(printf '%s\n' $files | grep -E '(CMakeLists\.txt|\.cmake|\.sh)$' | grep -v '^tests/check_comments\.sh$')
comments() {
  { [ -n "$cxx" ] && printf '%s\n' $cxx | xargs perl -ne \
      'print "$ARGV:$.:$2\n" if m{(//|/\*|^\s*\*)(.*)}; close ARGV if eof' 2>/dev/null
    [ -n "$hash" ] && printf '%s\n' $hash | xargs perl -ne \
      'print "$ARGV:$.:$2\n" if m{(^|\s)#(.*)}; close ARGV if eof' 2>/dev/null
  } | grep -v 'contract-figure'
}
unit='(ns|µs|us|ms|s|min|MB|GB)'
num='[0-9][0-9.,]*'
rules=(
  "timing before and after|${num} ?${unit}? ?(→|->) ?${num} ?${unit}\\b"
  "speed-up|\\b${num} ?(×|times) (faster|slower|as fast)|\\b${num} ?% (faster|slower|less CPU|more CPU|less time|more time)"
  "share a profile showed|\\bwas (a|an|one) (half|third|quarter|fifth|sixth|seventh|eighth|ninth|tenth) of\\b"
  "date|\\b20[0-9][0-9]-[01][0-9]-"
)
all=$(comments)
status=0
for rule in "${rules[@]}"; do
  name=${rule%%|*}
  pattern=${rule#*|}
  bad=$(printf '%s\n' "$all" | grep -E -- "^[^:]+:[0-9]+:.*(${pattern})")
  if [ -n "$bad" ]; then
    echo "a comment carries a ${name} (the lasting reason in the comment, figures in docs/results/, history in git; \"contract-figure\" marks a contract):"
    echo "$bad"
    status=1
  fi
done
echo "checked the comments of $(printf '%s\n' $files | wc -l) files: $([ $status -eq 0 ] && echo clean || echo VIOLATIONS)"
exit $status
