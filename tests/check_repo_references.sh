#!/usr/bin/env bash
# Fails, naming file and line, when a tracked file points outside the repository (the study's
# background notes a clone does not have) or tags a comment with a tracker issue number: what the
# code cites must be in the repository, and history lives in git.
set -u
root=${1:?usage: check_repo_references.sh SOURCE_DIR}
cd "$root" || exit 2
# Spelt in pieces so this file does not match itself.
dots='\.\.'
outside="${dots}/shared|reference-algorithms|field-notes|record-review-notes|/style\.md|\bstyle\.md|toolchain\.md|reference-data/README"
tag='[Ii]ssues? #''[0-9]'
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  files=$(git ls-files -- core devices ui app tests assets scripts cmake docs CMakeLists.txt README.md .ci)
else
  files=$(find core devices ui app tests assets scripts cmake docs CMakeLists.txt README.md .ci -type f 2>/dev/null)
fi
status=0
bad=$(printf '%s\n' $files | grep -v '^tests/check_repo_references.sh$' | xargs grep -InE "$outside" 2>/dev/null)
if [ -n "$bad" ]; then
  echo "cites a file outside the repository (write it into docs/ and cite that):"; echo "$bad"; status=1
fi
bad=$(printf '%s\n' $files | grep -v '^tests/check_repo_references.sh$' | xargs grep -InE "$tag" 2>/dev/null)
if [ -n "$bad" ]; then
  echo "tags an issue number (say why the code is as it is; history lives in git):"; echo "$bad"; status=1
fi
# A cited file of the repository exists: from the checkout's root, or as the end of a path (a README
# citing its own subfolders, a list that names a folder once). Moving or renaming a file must carry
# its citations along.
cited='(?<![A-Za-z0-9_./-])(core|devices|ui|app|tests|docs|scripts|cmake|assets|sessions)/[A-Za-z0-9_./-]*[A-Za-z0-9_]\.(h|cpp|md|sh|py|json|cmake|txt)\b'
all_files=$(printf '%s\n' $files)$'\n'
bad=$(printf '%s\n' $files | xargs grep -IonP "$cited" 2>/dev/null | while IFS=: read -r file line path; do
  [ -e "$path" ] || [[ "$all_files" == *"/$path"$'\n'* ]] || echo "$file:$line: $path"
done)
if [ -n "$bad" ]; then
  echo "cites a file the repository does not have (moved or renamed? cite where it is now):"; echo "$bad"; status=1
fi
echo "checked $(printf '%s\n' $files | wc -l) files: $([ $status -eq 0 ] && echo clean || echo VIOLATIONS)"
exit $status
