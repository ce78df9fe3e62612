#!/usr/bin/env bash
# Rebuilds each fuzz corpus in tests/fuzz/corpus/TARGET/ as a small set of inputs that covers
# every code edge the corpus and everything fuzzing runs have found since cover
# (build-fuzz/fuzz-work/TARGET/, written by tests/fuzz/run.sh): libFuzzer's -merge=1 with
# -use_counters=0, so that edges count and hit counts do not (a tenth of the files, the same
# edges; the fuzzers find the counts again within seconds).
#
#   tests/fuzz/minimize.sh [TARGET...]        (default: scene expression patch cache_entry exr_part)
set -euo pipefail
cd "$(dirname "$0")/../.."
targets=("$@")
((${#targets[@]})) || targets=(scene expression patch cache_entry exr_part)
build="${LANCER_FUZZ_BUILD:-build-fuzz}"
for target in "${targets[@]}"; do
  merged=$(mktemp -d)
  mkdir -p "$build/fuzz-work/$target"
  "$build/fuzz/fuzz_$target" -merge=1 -use_counters=0 -timeout=10 -rss_limit_mb=2048 "$merged" "tests/fuzz/corpus/$target" \
    "$build/fuzz-work/$target" >"$build/fuzz-merge-$target.log" 2>&1
  rm -rf "tests/fuzz/corpus/$target"
  mv "$merged" "tests/fuzz/corpus/$target"
  chmod 755 "tests/fuzz/corpus/$target"
  echo "minimize: $target: $(ls "tests/fuzz/corpus/$target" | wc -l) files, $(du -sh "tests/fuzz/corpus/$target" | cut -f1)" >&2
done
