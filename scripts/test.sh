#!/usr/bin/env bash
# All tests: the release build's suite, the same suite under AddressSanitizer +
# UndefinedBehaviorSanitizer, each libFuzzer target for FUZZ_SECONDS (default 30), and the
# aarch64 cross build with its tests under qemu-user (scripts/arm64.sh).
# FIELDLINES_TEST_STAGES selects stages (default "release asan fuzz arm64").
set -euo pipefail
cd "$(dirname "$0")/.."
stages="${FIELDLINES_TEST_STAGES:-release asan fuzz arm64}"
for stage in $stages; do
  echo "=== test stage: $stage ==="
  case "$stage" in
    release) ctest --preset release --output-on-failure ;;
    asan)
      cmake --preset asan >/dev/null
      cmake --build --preset asan -j"$(nproc)"
      ctest --preset asan --output-on-failure ;;
    fuzz) bash scripts/fuzz.sh ;;
    arm64) bash scripts/arm64.sh ;;
    *) echo "unknown test stage '$stage'" >&2; exit 2 ;;
  esac
done
