#!/usr/bin/env bash
# Fails, naming the file and line, when an include goes up a floor: core/ including UI, GL or device
# headers, or, inside ui/, scene including model or either of them including what draws.
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
# Inside ui/ the floors run one way too: ui/scene (pure builders, camera, picking; its gl_* files
# draw) below ui/model (tab states, jobs, caches), both below what draws (tabs, widgets, platform,
# app). So scene never includes model, and neither includes a drawing floor.
bad_scene=$(grep -RInE '#[[:space:]]*include[[:space:]]*"ui/(model|tabs|widgets|app)/' "$root/ui/scene" \
  --include='*.h' --include='*.cpp' 2>/dev/null)
bad_scene_gl=$(grep -RInE '#[[:space:]]*include[[:space:]]*([<"](imgui|backends/imgui|GL/|GLFW/|epoxy/)|"ui/platform/)' \
  "$root/ui/scene" --include='*.h' --include='*.cpp' 2>/dev/null | grep -v '/ui/scene/gl_')
bad_model_up=$(grep -RInE '#[[:space:]]*include[[:space:]]*"ui/(tabs|widgets|app|platform)/' "$root/ui/model" \
  --include='*.h' --include='*.cpp' 2>/dev/null)
# A tab's panels read its state: the Record and Devices tabs reach the controllers only through
# their state in ui/model.
bad_tabs_devices=$(grep -RInE '#[[:space:]]*include[[:space:]]*"devices/' "$root/ui/tabs/record" "$root/ui/tabs/devices" \
  --include='*.h' --include='*.cpp' 2>/dev/null)
if [ -n "$bad_tabs_devices" ]; then
  echo "ui/tabs/record and ui/tabs/devices must not include devices/ headers (their state exposes what panels need):"
  echo "$bad_tabs_devices"; status=1
fi
if [ -n "$bad_scene" ]; then
  echo "ui/scene/ may include only core, devices and ui/scene (ui/model builds on it, not the other way):"; echo "$bad_scene"; status=1
fi
if [ -n "$bad_scene_gl" ]; then
  echo "only ui/scene/gl_* may include ImGui, GL or the platform:"; echo "$bad_scene_gl"; status=1
fi
if [ -n "$bad_model_up" ]; then
  echo "ui/model/ must not include what draws (ui/tabs, ui/widgets, ui/app, ui/platform):"; echo "$bad_model_up"; status=1
fi
# Inside core, data flows one way: a folder includes only folders before it in this list (files
# and the hand model first; processing before what reports on it). A new folder joins the list.
core_order=(common platform stats geometry layout hand visibility metric optimise io figures processing results reports review calibration session export poses)
for ((i = 0; i < ${#core_order[@]}; i++)); do
  folder=${core_order[$i]}
  [ -d "$root/core/$folder" ] || continue
  later=("${core_order[@]:$((i + 1))}")
  [ ${#later[@]} -gt 0 ] || continue
  alternatives=$(IFS='|'; echo "${later[*]}")
  back=$(grep -RInE "#[[:space:]]*include[[:space:]]*\"core/($alternatives)/" "$root/core/$folder" --include='*.h' --include='*.cpp' 2>/dev/null)
  if [ -n "$back" ]; then
    echo "core/$folder may include only core/{${core_order[*]:0:$i}} (core's data flow runs one way):"; echo "$back"; status=1
  fi
done
for d in "$root"/core/*/; do
  name=$(basename "$d")
  [[ " ${core_order[*]} " == *" $name "* ]] || { echo "core/$name is not in check_layering.sh's core order: add it"; status=1; }
done
n=$(find "$root/core" "$root/ui/model" "$root/ui/scene" -name '*.h' -o -name '*.cpp' | wc -l)
echo "checked $n core and ui files: $([ $status -eq 0 ] && echo clean || echo VIOLATIONS)"
exit $status
