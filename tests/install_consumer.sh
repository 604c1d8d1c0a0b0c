#!/usr/bin/env bash
# Installs the build into a temporary prefix and builds two consumers against it that only call
# find_package(fieldlines): tests/consumer/detect (a robot: COMPONENTS detect, links
# fieldlines::detect alone) and tests/consumer/core (a tool: fieldlines::core, all four).
# Usage: install_consumer.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build="$1" source="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cmake_dir="$(dirname "$(find "$work/prefix" -name fieldlinesConfigVersion.cmake | head -1)")"
test -f "$cmake_dir/fieldlines_detect_targets.cmake"
test -x "$work/prefix/bin/fieldlines"
"$work/prefix/bin/fieldlines" --version
# The robot's installed target names only OpenCV core/imgproc and nlohmann-json.
if grep -nE 'Eigen|Threads|imgcodecs|videoio|fieldlines::(data|train|synth)' \
     "$cmake_dir"/fieldlines_detect_targets*.cmake; then
  echo "install_consumer: fieldlines::detect's installed target names a dependency it must not have" >&2
  exit 1
fi
# Each consumer is compiled like the build it installs (e.g. with the sanitizers of preset asan).
cache_value() { sed -n "s/^$1:[A-Z]*=//p" "$build/CMakeCache.txt"; }
for consumer in detect core; do
  cmake -S "$source/tests/consumer/$consumer" -B "$work/build-$consumer" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_CXX_COMPILER="$(cache_value CMAKE_CXX_COMPILER)" \
    -DCMAKE_CXX_FLAGS="$(cache_value CMAKE_CXX_FLAGS)" \
    -DCMAKE_EXE_LINKER_FLAGS="$(cache_value CMAKE_EXE_LINKER_FLAGS)" \
    -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
  cmake --build "$work/build-$consumer" >/dev/null
done
# The robot's executable needs no library of ours but libfieldlines_detect.
if ldd "$work/build-detect/consumer" | grep -E 'libfieldlines_(data|train|synth)'; then
  echo "install_consumer: the detect consumer links a tuning library" >&2
  exit 1
fi
"$work/build-detect/consumer" "$source/assets/default_thresholds.json"
"$work/build-core/consumer"
