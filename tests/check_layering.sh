#!/usr/bin/env bash
# Fails, naming the file and line, when core/ or ui/model/ includes a UI, GL or device header.
set -u
root=${1:?usage: check_layering.sh SOURCE_DIR}
pattern='#[[:space:]]*include[[:space:]]*[<"](imgui|backends/imgui|GL/|GLFW/|epoxy/|devices/|ui/)'
bad=$(grep -RInE "$pattern" "$root/core" --include='*.h' --include='*.cpp' 2>/dev/null)
bad_model=$(grep -RInE '#[[:space:]]*include[[:space:]]*[<"](imgui|backends/imgui|GL/|GLFW/|epoxy/)' \
  "$root/ui/model" --include='*.h' --include='*.cpp' 2>/dev/null)
status=0
if [ -n "$bad" ]; then
  echo "core/ must not include UI, GL or device headers:"; echo "$bad"; status=1
fi
if [ -n "$bad_model" ]; then
  echo "ui/model/ must not include ImGui or GL headers:"; echo "$bad_model"; status=1
fi
n=$(find "$root/core" -name '*.h' -o -name '*.cpp' | wc -l)
echo "checked $n core files: $([ $status -eq 0 ] && echo clean || echo VIOLATIONS)"
exit $status
