#!/usr/bin/env bash
# All tests: the release build's suite; every window-free test and one window smoke test under
# AddressSanitizer + UndefinedBehaviorSanitizer; each libFuzzer target for FUZZ_SECONDS (default
# 30), two at a time; and the aarch64 cross build with its tests under qemu-user
# (scripts/arm64.sh). Per-stage times: docs/testing.md.
# FIELDLINES_TEST_STAGES selects stages (default "release asan fuzz arm64").
set -euo pipefail
cd "$(dirname "$0")/.."
stages="${FIELDLINES_TEST_STAGES:-release asan fuzz arm64}"
started=$SECONDS
# The arm64 stage's cross compiler and sysroot are mostly downloads: fetched in the background
# while the other stages compile and test, so the network wait costs no CPU time.
prepare_log=build/arm64-prepare.log
prepare_pid=""
if [[ " $stages " == *" arm64 "* ]]; then
  mkdir -p build
  bash scripts/arm64.sh --prepare >"$prepare_log" 2>&1 &
  prepare_pid=$!
fi
for stage in $stages; do
  echo "=== test stage: $stage ==="
  stage_start=$SECONDS
  case "$stage" in
    release) ctest --preset release --output-on-failure ;;
    asan)
      cmake --preset asan >/dev/null
      cmake --build --preset asan -j"$(nproc)"
      ctest --preset asan --output-on-failure
      ctest --preset asan-window-smoke --output-on-failure ;;
    fuzz) bash scripts/fuzz.sh ;;
    arm64)
      wait "$prepare_pid" || { cat "$prepare_log" >&2; echo "arm64: preparing the cross build FAILED" >&2; exit 1; }
      bash scripts/arm64.sh ;;
    *) echo "unknown test stage '$stage'" >&2; exit 2 ;;
  esac
  echo "=== test stage $stage: passed in $((SECONDS - stage_start)) s ==="
done
echo "=== all test stages passed in $((SECONDS - started)) s ==="
