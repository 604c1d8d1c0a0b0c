#!/usr/bin/env bash
# Builds the libFuzzer targets (preset `fuzz`, clang) and runs each for FUZZ_SECONDS (default 30)
# from a copy of its committed seed corpus, FUZZ_PARALLEL (default 2: one per core) at a time.
# Any crash, leak or sanitizer report fails. Prints executions per second and coverage per
# target; a finding is kept in build/fuzz/findings/<target>/ (add it to the corpus once fixed).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${FUZZ_SECONDS:-30}"
parallel="${FUZZ_PARALLEL:-2}"
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j"$(nproc)"

# run_one FUZZER: runs it, prints its one-line verdict, returns non-zero on a finding.
run_one() {
  local fuzzer="$1" name work log execs cov
  name="$(basename "$fuzzer")"
  work="$(mktemp -d)"
  cp -r "tests/fuzz/corpus/$name/." "$work/" 2>/dev/null || true
  log="$work/log.txt"
  if "$fuzzer" -max_total_time="$seconds" -print_final_stats=1 -artifact_prefix="$work/" "$work" >"$log" 2>&1; then
    execs=$(grep -o 'average_exec_per_sec: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
    cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || echo "?")
    echo "fuzz: $name ok — ${seconds}s, ${execs} exec/s, coverage ${cov} edges"
    rm -rf "$work"
    return 0
  fi
  mkdir -p build/fuzz/findings/"$name"
  cp "$log" "$work"/crash-* "$work"/leak-* "$work"/timeout-* "$work"/oom-* build/fuzz/findings/"$name"/ 2>/dev/null || true
  { echo "fuzz: $name FAILED (input and log kept in build/fuzz/findings/$name); last lines:"; tail -40 "$log"; } >&2
  rm -rf "$work"
  return 1
}

status=0
pids=()
for fuzzer in build/fuzz/tests/fuzz/*_fuzz; do
  run_one "$fuzzer" &
  pids+=("$!")
  if ((${#pids[@]} >= parallel)); then
    wait "${pids[0]}" || status=1
    pids=("${pids[@]:1}")
  fi
done
for pid in "${pids[@]}"; do wait "$pid" || status=1; done
exit "$status"
