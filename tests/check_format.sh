#!/usr/bin/env bash
# Fails, naming the files, when a C++ file in the repository is not as .clang-format lays it out.
# Fix with: git ls-files '*.h' '*.cpp' | xargs clang-format -i
set -u
root=${1:?usage: check_format.sh SOURCE_DIR}
cd "$root" || exit 2
command -v clang-format >/dev/null || { echo "clang-format is not installed (scripts/install-deps installs it)"; exit 1; }
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  files=$(git ls-files -- '*.h' '*.cpp')
else
  files=$(find . -name '*.h' -o -name '*.cpp' | grep -v '^./build/')
fi
bad=$(printf '%s\n' $files | xargs clang-format --dry-run 2>&1 | grep -oE '^[^:]+\.(h|cpp):' | sort -u | tr -d ':')
if [ -n "$bad" ]; then
  echo "not formatted ($(clang-format --version | head -1)):"; echo "$bad"
  exit 1
fi
echo "checked $(printf '%s\n' $files | wc -l) files: formatted"
