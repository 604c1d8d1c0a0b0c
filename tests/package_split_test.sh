#!/usr/bin/env bash
# The .deb split (cmake/packaging.cmake) holds what each package promises: the robot's runtime
# package is libfieldlines_detect.so alone and depends on no tuning library, Eigen or imgcodecs;
# the tuning libraries, the headers + CMake package, the tools and the Python module each go
# to their own package. Runs cpack on the build into a temporary folder.
# Usage: package_split_test.sh BUILD_DIR
set -euo pipefail
build="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fail() { echo "package_split: $*" >&2; exit 1; }
cpack --config "$build/CPackConfig.cmake" -G DEB -B "$work" >"$work/cpack.log" 2>&1 || { cat "$work/cpack.log" >&2; fail "cpack failed"; }
deb() { ls "$work"/"$1"_*.deb 2>/dev/null | head -1; }
files() { dpkg-deb -c "$1" | awk '$1 !~ /^d/ {print $6}'; }  # regular files and links, ./usr/...

detect="$(deb libfieldlines-detect0)"; libs="$(deb libfieldlines0)"; dev="$(deb libfieldlines-dev)"
tools="$(deb fieldlines)"
for p in "$detect" "$libs" "$dev" "$tools"; do [[ -n "$p" ]] || fail "missing package in $(ls "$work")"; done

# The robot's package: the detect library and nothing else.
extra="$(files "$detect" | grep -v '/libfieldlines_detect\.so\.' || true)"
[[ -z "$extra" ]] || fail "libfieldlines-detect0 holds more than libfieldlines_detect.so: $extra"
files "$detect" | grep -q 'libfieldlines_detect\.so\.' || fail "libfieldlines-detect0 has no library"
depends="$(dpkg-deb -f "$detect" Depends)"
echo "libfieldlines-detect0 Depends: $depends"
if grep -qiE 'eigen|imgcodecs|videoio|libfieldlines0|tbb|gomp' <<<"$depends"; then
  fail "the robot's package depends on a tuning library: $depends"
fi
grep -q 'libopencv-imgproc' <<<"$depends" || fail "libfieldlines-detect0 should depend on OpenCV imgproc: $depends"

# The tuning libraries, the headers and the tools each in their own package.
files "$libs" | grep -q 'libfieldlines_train\.so\.' || fail "libfieldlines0 has no train library"
files "$libs" | grep -q 'libfieldlines_detect' && fail "libfieldlines0 repeats the detect library"
files "$dev" | grep -q 'include/fieldlines/detect/detector.hpp' || fail "libfieldlines-dev has no detect headers"
files "$dev" | grep -q 'fieldlinesConfig.cmake' || fail "libfieldlines-dev has no CMake package"
files "$tools" | grep -q '/bin/fieldlines$' || fail "the fieldlines package has no CLI"
grep -q 'libfieldlines-detect0' <<<"$(dpkg-deb -f "$tools" Depends)" || fail "the tools do not depend on the runtime package"
if ls "$build"/python/fieldlines*.so >/dev/null 2>&1; then  # the module was built
  python="$(deb python3-fieldlines)"
  [[ -n "$python" ]] || fail "the Python module is built but has no package"
  files "$python" | grep -qE 'dist-packages/fieldlines\..*\.so$' || fail "python3-fieldlines has no module"
fi
echo "package_split: $(ls "$work"/*.deb | wc -l) packages, each holds what it promises"
