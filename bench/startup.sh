#!/usr/bin/env bash
# Start-up benchmark (not a test): a 1x1 render of each scene, whole process, by one or two lancer
# executables, with the shader caches warm, with lancer's SPIR-V cache off (it specialises the
# tracer again), with Mesa's off (lavapipe compiles it again with LLVM) and with both off (a
# first run). The runs alternate between the executables and the cache states so that drift on
# a shared machine hits all alike. Prints one Markdown row per scene and executable: the median
# wall time of each state.
#
#   bench/startup.sh [-n runs=5] LANCER [LANCER2] [-- SCENE...]
#   bench/startup.sh /tmp/lancer-5d901f1 build/lancer -- scenes/seed.toml bench/torus_shape.toml
set -euo pipefail
cd "$(dirname "$0")/.."
runs=5
while getopts "n:" opt; do
  case $opt in
    n) runs=$OPTARG ;;
    *) echo "usage: $0 [-n runs] LANCER [LANCER2] [-- SCENE...]" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
executables=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do executables+=("$1"); shift; done
[ $# -gt 0 ] && shift
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(scenes/seed.toml scenes/many.toml bench/torus_shape.toml scenes/teapot.toml)
[ ${#executables[@]} -ge 1 ] || { echo "usage: $0 [-n runs] LANCER [LANCER2] [-- SCENE...]" >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

source bench/machine.sh
machine_description
states=(warm lancer_cold mesa_cold both_cold)
run_one() {  # executable index, scene, state
  local exe=${executables[$1]} env=()
  case $3 in
    lancer_cold) env=(LANCER_CACHE_DISABLE=1) ;;
    mesa_cold) env=(MESA_SHADER_CACHE_DISABLE=true) ;;
    both_cold) env=(LANCER_CACHE_DISABLE=1 MESA_SHADER_CACHE_DISABLE=true) ;;
  esac
  local start end
  start=$(date +%s.%N)
  env "${env[@]}" $exe render "$2" -o "$out/frame.png" --width 1 --height 1 -q
  end=$(date +%s.%N)
  awk -v a="$start" -v b="$end" 'BEGIN { print b - a }' >> "$out/$1.$(basename "$2").$3"
}
median() { sort -g "$1" | awk '{v[NR]=$1} END {print (NR % 2) ? v[(NR+1)/2] : (v[NR/2] + v[NR/2+1]) / 2}'; }

for scene in "${scenes[@]}"; do
  for e in "${!executables[@]}"; do run_one "$e" "$scene" warm; done  # fills the caches
done
for ((r = 0; r < runs; r++)); do
  for scene in "${scenes[@]}"; do
    for state in "${states[@]}"; do
      for e in "${!executables[@]}"; do run_one "$e" "$scene" "$state"; done
    done
  done
done

echo
echo "Medians of $runs runs, seconds of wall time, a 1x1 render:"
echo
echo "| scene | lancer | warm | lancer's cache off | Mesa's cache off | both off |"
echo "|---|---|---|---|---|---|"
for scene in "${scenes[@]}"; do
  for e in "${!executables[@]}"; do
    row="| $(basename "$scene" .toml) | ${executables[$e]}"
    for state in "${states[@]}"; do row="$row | $(printf '%.3f' "$(median "$out/$e.$(basename "$scene").$state")")"; done
    echo "$row |"
  done
done
