#!/usr/bin/env bash
# Benchmark (not a test): the cost of an animation, scenes/orbit.toml on the GPU backend, with
# the one-time start-up (Vulkan instance, device, pipeline) separated from the per-frame cost.
# Then the same frames rendered one process each, as a render-per-frame script would, to show
# what keeping the device, pipeline and buffers alive across frames saves.
#
#   bench/orbit.sh [frames=24] [width=640] [height=360] [samples=2]
#
# Builds first with ./setup.sh build if build/lancer is missing.
set -euo pipefail
cd "$(dirname "$0")/.."
frames="${1:-24}" width="${2:-640}" height="${3:-360}" samples="${4:-2}"
[ -x build/lancer ] || ./setup.sh build
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
size=(--width "$width" --height "$height" --samples "$samples")
now() { date +%s.%N; }

# One warm-up render fills Mesa's shader cache, so no run below pays the one-time JIT.
./build/lancer render scenes/orbit.toml --frames 0 --width 64 --height 36 -q -o "$out/warm.png"

echo "scenes/orbit.toml, ${width}x${height}, $((samples * samples)) rays/pixel, frames 0-$((frames - 1)), gpu"
t0=$(now)
log=$(./build/lancer render scenes/orbit.toml "${size[@]}" --frames "0-$((frames - 1))" --force \
        -o "$out/seq_%03d.png" 2>&1)
t1=$(now)
summary=$(tail -n 1 <<<"$log")
startup=$(sed -E 's/.*start-up ([0-9.]+) s.*/\1/' <<<"$summary")
first=$(sed -E 's/.*first frame ([0-9.]+) s.*/\1/' <<<"$summary")
per_frame=$(sed -E 's/.*then ([0-9.]+) s\/frame.*/\1/' <<<"$summary")
# Fastest and slowest of frames 2..N, from the per-frame lines.
read -r fmin fmax < <(grep -E ': frame [0-9]+ \(' <<<"$log" | tail -n +2 | sed -E 's/.*, ([0-9.]+) s$/\1/' |
                      sort -g | awk 'NR==1{min=$1} {max=$1} END{print min, max}')
awk -v w="$t0" -v e="$t1" -v n="$frames" -v s="$startup" -v f="$first" -v p="$per_frame" -v lo="$fmin" -v hi="$fmax" 'BEGIN{
  printf "one process, %d frames:   %.3f s wall\n", n, e - w
  printf "  start-up (device, buffers, pipeline and its compile; once): %.3f s\n", s
  printf "  first frame:                        %.3f s\n", f
  printf "  frames 2..%d:                       %.3f s/frame (min %.3f, max %.3f)\n", n, p, lo, hi
}'

# The same scene, one process per frame (scene load, Vulkan start-up and pipeline each time).
runs=$(( frames < 6 ? frames : 6 ))
t0=$(now)
for k in $(seq 0 $((runs - 1))); do
  ./build/lancer render scenes/orbit.toml "${size[@]}" --frames "$k" -q -o "$out/single_$k.png"
done
t1=$(now)
awk -v w="$t0" -v e="$t1" -v n="$runs" -v p="$per_frame" 'BEGIN{
  single = (e - w) / n
  printf "one process per frame, %d frames: %.3f s/frame wall; in one process a frame costs %.2fx less\n", n, single, single / p
}'
