#!/usr/bin/env bash
# The README is a user's page that stays true: every command marked runnable runs, it stays short,
# and neither it nor docs/ reads like a lab notebook.
#
# Convention: a line `<!-- runnable -->` directly above a ```bash or ```python fence marks that
# block as runnable. The runnable blocks run in README order, in one fresh temporary folder (so a
# later block may use what an earlier one wrote), with HOME and the XDG folders inside it:
#   bash blocks   `bash -euo pipefail`, the built CLI (and studio) first on PATH;
#   python blocks Debian's /usr/bin/python3 with PYTHONPATH at the built module (skipped, and
#                 said so, only in a build that has no module: sanitized or without pybind11).
# Unmarked blocks (set-up, the robot's C++, CMake, the studio) are checked in other ways: the two
# set-up lines must be the strings .ci/run and scripts/ use; the C++ and CMake lines must be the
# calls that tests/consumer/detect (built by the install_consumer test) compiles.
#
# Usage: readme_test.sh SOURCE_DIR CLI_DIR STUDIO_DIR PYTHON_DIR HAVE_PYTHON(0|1)
set -euo pipefail
abs() { realpath -m "$1"; }
source_dir="$(abs "$1")" cli_dir="$(abs "$2")" studio_dir="$(abs "$3")" python_dir="$(abs "$4")" have_python="$5"
readme="$source_dir/README.md"
failures=0
fail() {
  echo "readme_test: $*" >&2
  failures=$((failures + 1))
}

# --- Size and words -------------------------------------------------------------------------
size=$(wc -c <"$readme")
((size <= 12000)) || fail "README.md is $size bytes, more than 12000"

# History belongs in CHANGELOG.md and commit messages, not in pages a user reads. In docs/ the
# word "stop" is also a button and a std::stop_token, so there only its history uses are refused.
history='\b(session|sessions|today|earlier|re-?measured)\b|\bwas\b.*\bbefore\b'
history_stop='\b(this|that|last|previous|one|each|every|next) stop\b|\bstop before that\b|\bstops? ago\b'
check_words() {
  local file="$1" pattern="$2" hits
  if hits=$(grep -niE "$pattern" "$file"); then
    fail "${file#"$source_dir"/} has history words:"$'\n'"$hits"
  fi
}
check_words "$readme" "$history|\bstop\b"
for doc in "$source_dir"/docs/*.md; do
  check_words "$doc" "$history|$history_stop"
done

# --- Links ----------------------------------------------------------------------------------
while IFS= read -r target; do
  target="${target%%#*}"
  [[ -z "$target" || "$target" == http* ]] && continue
  [[ -e "$source_dir/$target" ]] || fail "README.md links to $target, which does not exist"
done < <(grep -oE '\]\([^)]+\)' "$readme" | sed -E 's/^\]\((.*)\)$/\1/' | sort -u)

# --- The benchmark markers scripts/benchmarks.sh fills -----------------------------------------
for kind in speed accuracy; do
  begin=$(grep -c "^<!-- benchmarks:$kind:begin -->\$" "$readme" || true)
  end=$(grep -c "^<!-- benchmarks:$kind:end -->\$" "$readme" || true)
  [[ "$begin" == 1 && "$end" == 1 ]] || fail "README.md needs one benchmarks:$kind begin and end marker (has $begin, $end)"
  first=$(grep -n "^<!-- benchmarks:$kind:begin -->\$" "$readme" | cut -d: -f1 | head -1)
  last=$(grep -n "^<!-- benchmarks:$kind:end -->\$" "$readme" | cut -d: -f1 | head -1)
  if [[ -z "$first" || -z "$last" ]] || ((first >= last)); then
    fail "benchmarks:$kind: begin must come before end"
  fi
  sed -n "${first:-1},${last:-1}p" "$readme" | grep -q '^| ' || fail "benchmarks:$kind holds no table"
done

# --- The set-up lines are the ones CI and the scripts run --------------------------------------
demo_line='bash scripts/setup.sh && bash scripts/demo.sh'
test_line='bash scripts/setup.sh && bash scripts/test.sh'
for line in "$demo_line" "$test_line"; do
  grep -qF "$line" "$readme" || fail "README.md lacks the set-up line: $line"
done
grep -qxF "$test_line" "$source_dir/.ci/run" || fail ".ci/run does not run exactly: $test_line"
for script in setup demo test; do
  [[ -f "$source_dir/scripts/$script.sh" ]] || fail "scripts/$script.sh is missing"
done
# What the README says of them: setup builds the release preset, demo opens that build.
# shellcheck disable=SC2016  # the literal text of the script
grep -qF 'preset="${1:-release}"' "$source_dir/scripts/setup.sh" || fail "scripts/setup.sh no longer builds the release preset by default"
grep -qF 'build/release/app' "$source_dir/scripts/demo.sh" || fail "scripts/demo.sh no longer runs build/release's programs"

# --- The robot's snippet is what the consumer test compiles -----------------------------------
consumer="$source_dir/tests/consumer/detect"
for call in 'fieldlines::load_thresholds_file(' 'fieldlines::LineDetector detector(config.detector, config.thresholds);' \
            'detector.detect(' 'fieldlines::Label::Marking'; do
  grep -qF "$call" "$readme" || fail "README.md's C++ snippet lacks: $call"
  grep -qF "$call" "$consumer/main.cpp" || fail "tests/consumer/detect/main.cpp no longer compiles: $call"
done
for line in 'find_package(fieldlines 0.1 REQUIRED COMPONENTS detect)' 'fieldlines::detect)'; do
  grep -qF "$line" "$readme" || fail "README.md's CMake lines lack: $line"
  grep -qF "$line" "$consumer/CMakeLists.txt" || fail "tests/consumer/detect/CMakeLists.txt lacks: $line"
done

# --- Run the runnable blocks -------------------------------------------------------------------
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/run" "$work/home" "$work/blocks"
# Split the README: block N goes to blocks/N.bash or blocks/N.python.
awk -v dir="$work/blocks" '
  /^<!-- runnable -->$/ { marked = 1; next }
  marked && /^```(bash|python)$/ { lang = substr($0, 4); n++; file = sprintf("%s/%02d.%s", dir, n, lang); inblock = 1; marked = 0; next }
  marked { printf "a runnable marker is not directly above a ```bash or ```python fence: %s\n", $0 > "/dev/stderr"; bad = 1; marked = 0 }
  inblock && /^```$/ { inblock = 0; close(file); next }
  inblock { print > file }
  END { exit bad }' "$readme" || fail "malformed runnable marker"
mapfile -t blocks < <(find "$work/blocks" -type f | sort)
((${#blocks[@]} > 0)) || fail "README.md has no runnable block"

export HOME="$work/home" XDG_DATA_HOME="$work/home/data" XDG_CONFIG_HOME="$work/home/config"
export PATH="$cli_dir:$studio_dir:$PATH"
for block in "${blocks[@]}"; do
  name="$(basename "$block")"
  case "$name" in
    *.bash)
      echo "--- README block $name" && cat "$block"
      (cd "$work/run" && bash -euo pipefail "$block") || fail "README block $name failed (above)" ;;
    *.python)
      if [[ "$have_python" != 1 ]]; then
        echo "--- README block $name not run: this build has no Python module"
        continue
      fi
      echo "--- README block $name" && cat "$block"
      (cd "$work/run" && PYTHONPATH="$python_dir" /usr/bin/python3 "$block") || fail "README block $name failed (above)" ;;
  esac
done

if ((failures)); then
  echo "readme_test: $failures problem(s)" >&2
  exit 1
fi
echo "readme_test: ${#blocks[@]} runnable blocks ran; README.md is $size bytes"
