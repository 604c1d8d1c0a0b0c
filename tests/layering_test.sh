#!/usr/bin/env bash
# The include layering of the source tree (docs/architecture.md): dependencies point one way,
#   core/detect <- core/data <- core/train <- core/synth;  gui/model -> core;
#   gui/panels (ImGui drawing only) -> gui/model, core;  app/cli -> core, bench/peers;
#   bench/peers -> detect;  app/studio (window, GL, GLFW, main loop) -> gui/panels, gui/model, core;
#   python (the module) -> detect, data, train;
# no window-system include (ImGui, GLFW, OpenGL) in core/ or gui/model/, no GLFW or OpenGL in
# gui/panels/, and no source file in gui/'s root; every quoted include
# is either a file beside the includer, one from its library's source root (core/<lib>/src), or
# qualified from the project root or fieldlines/<lib>/.
# Usage: layering_test.sh SOURCE_DIR. Prints every violation; exits 1 if there is one.
set -uo pipefail
cd "$1"
status=0
fail() { echo "layering: $*" >&2; status=1; }

# The layer of a path (a source file, or what an include names).
layer_of_file() {
  case "$1" in
    core/detect/*) echo detect ;; core/data/*) echo data ;; core/train/*) echo train ;;
    core/synth/*) echo synth ;; gui/model/*) echo model ;; gui/panels/*) echo panels ;; gui/*) echo gui ;;
    app/cli/*) echo cli ;; app/studio/*) echo studio ;; python/*) echo python ;;
    bench/peers/*) echo peers ;; *) echo other ;;
  esac
}
layer_of_include() {
  case "$1" in
    fieldlines/detect/*) echo detect ;; fieldlines/data/*) echo data ;;
    fieldlines/train/*) echo train ;; fieldlines/synth/*) echo synth ;;
    gui/model/*) echo model ;; gui/panels/*) echo panels ;; gui/*) echo gui ;; app/cli/*) echo cli ;;
    app/studio/*) echo studio ;; bench/peers/*) echo peers ;;
    tests/*) echo other ;; *) echo unknown ;;
  esac
}
# What each layer may include (besides itself).
allowed() {
  case "$1" in
    detect) echo "detect" ;;
    data) echo "detect data" ;;
    train) echo "detect data train" ;;
    synth) echo "detect data train synth" ;;
    model) echo "detect data train synth model" ;;
    panels) echo "detect data train synth model panels" ;;
    gui) echo "" ;;  # gui/'s root holds no sources: state is gui/model's, drawing gui/panels'
    cli) echo "detect data train synth peers cli" ;;
    peers) echo "detect peers" ;;
    studio) echo "detect data train synth model panels studio" ;;
    python) echo "detect data train" ;;
    other) echo "detect data train synth model panels cli studio peers other" ;;  # tests, bench, fuzzers
  esac
}

checked=0
while IFS= read -r file; do
  checked=$((checked + 1))
  layer="$(layer_of_file "$file")"
  dir="$(dirname "$file")"
  [[ "$layer" == gui ]] && fail "$file: gui/'s root holds no sources (gui/model: state, gui/panels: drawing, app/studio: window)"
  while IFS= read -r line; do
    [[ -z "$line" ]] && continue
    number="${line%%:*}"
    text="${line#*:}"
    where="$file:$number"
    if [[ "$text" =~ \#include[[:space:]]*\<(imgui|GLFW/|GL/|backends/imgui) ]] &&
       [[ "$layer" == detect || "$layer" == data || "$layer" == train || "$layer" == synth || "$layer" == model ]]; then
      fail "$where: window-system include in $layer: $text"
    fi
    if [[ "$text" =~ \#include[[:space:]]*\<(GLFW/|GL/|backends/imgui|imgui_impl_) ]] && [[ "$layer" == panels ]]; then
      fail "$where: GLFW or OpenGL include in gui/panels (the window is app/studio's): $text"
    fi
    # Angle brackets name our own headers too when they start with a layer's folder.
    if [[ "$text" =~ \#include[[:space:]]*\<((fieldlines|gui|app)/[^>]*)\> ]]; then
      name="${BASH_REMATCH[1]}"
    elif [[ "$text" =~ \#include[[:space:]]*\"([^\"]*)\" ]]; then
      name="${BASH_REMATCH[1]}"
      [[ "$name" == *..* ]] && { fail "$where: include climbs out of its folder: $name"; continue; }
      # A file beside the includer (or below it) belongs to the includer's layer, and so does
      # one named from its library's source root (core/<lib>/src, on that library's include path).
      [[ -f "$dir/$name" ]] && continue
      [[ "$file" =~ ^(core/[a-z]+)/src/ && -f "${BASH_REMATCH[1]}/src/$name" ]] && continue
    else
      continue
    fi
    target="$(layer_of_include "$name")"
    if [[ "$target" == unknown ]]; then
      fail "$where: include is neither beside the file nor path-qualified: $name"
    elif [[ " $(allowed "$layer") " != *" $target "* ]]; then
      fail "$where: $layer must not include $target ($name)"
    fi
  done < <(grep -n '#include' "$file")
done < <(find core gui app tests bench python -name '*.[ch]pp' 2>/dev/null | sort)

((checked > 50)) || fail "only $checked source files found: run from the project root"
((status == 0)) && echo "layering: $checked files, every include points down the layers"
exit "$status"
