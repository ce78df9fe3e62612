#!/usr/bin/env bash
# Runs each libFuzzer target for a bounded time on the sanitizer build (ASan + UBSan), starting
# from its corpus and the reproducers of bugs found before. Fails (exit code != 0) on any crash,
# sanitizer report, leak, timeout or memory blow-up; the input that caused it is written to
# build-fuzz/fuzz-artifacts/TARGET/ (add it to tests/fuzz/regressions/TARGET/ once fixed).
#
#   tests/fuzz/run.sh [SECONDS_PER_TARGET] [TARGET...]     (default 60 s; scene expression patch cache_entry exr_part obj ply)
#
# LANCER_FUZZ_TIMEOUT (default 10) is the time one input may take before it counts as a hang.
# LANCER_FUZZ_SEED fixes libFuzzer's random seed (CI uses 1, so that a red run can be replayed
# mutation for mutation); unset, every run explores from a new seed.
#
# Inputs the run finds interesting go to build-fuzz/fuzz-work/TARGET/, not into the repository;
# tests/fuzz/minimize.sh merges them into the corpora.
set -euo pipefail
cd "$(dirname "$0")/../.."

seconds="${1:-60}"
shift || true
targets=("$@")
((${#targets[@]})) || targets=(scene expression patch cache_entry exr_part obj ply)
build="${LANCER_FUZZ_BUILD:-build-fuzz}"
seed="${LANCER_FUZZ_SEED:-0}"  # 0: libFuzzer picks one
timeout="${LANCER_FUZZ_TIMEOUT:-10}"  # seconds per input; more on a machine busy with other work

# The sanitizers' options and leak suppressions are compiled into the fuzzers
# (cmake/sanitizers.cmake); stack traces need llvm-symbolizer (package llvm).

declare -A max_len=([scene]=16384 [expression]=5000 [patch]=16384 [cache_entry]=4096 [exr_part]=16384 [obj]=16384 [ply]=16384)
failed=()
for target in "${targets[@]}"; do
  binary="$build/fuzz/fuzz_$target"
  [ -x "$binary" ] || { echo "fuzz: $binary is missing: build the fuzz preset first (./setup.sh fuzz)" >&2; exit 2; }
  work="$build/fuzz-work/$target"
  artifacts="$build/fuzz-artifacts/$target"
  mkdir -p "$work" "$artifacts"
  log="$build/fuzz-$target.log"
  echo "fuzz: $target for ${seconds} s" >&2
  # -timeout: one input may take at most 10 s by default (the slowest legitimate ones seen take about 4 s
  # under ASan alone: an implicit surface of 2,000 characters whose roots the CPU reference finds); -rss_limit_mb: 2 GiB of memory at most.
  if "$binary" -max_total_time="$seconds" -timeout="$timeout" -rss_limit_mb=2048 -max_len="${max_len[$target]}" \
       -dict="tests/fuzz/$target.dict" -seed="$seed" -artifact_prefix="$artifacts/" -print_final_stats=1 \
       "$work" "tests/fuzz/corpus/$target" "tests/fuzz/regressions/$target" >"$log" 2>&1; then
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
    rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log")
    echo "fuzz: $target: $runs inputs in ${seconds} s ($rate/s), no crash, leak or timeout" >&2
  else
    echo "fuzz: $target FAILED; the end of $log:" >&2
    tail -40 "$log" >&2
    failed+=("$target")
  fi
done
if ((${#failed[@]})); then
  echo "fuzz: failed: ${failed[*]} (reproducers in $build/fuzz-artifacts/)" >&2
  exit 1
fi
