#!/usr/bin/env bash
# Benchmark (not a test): scenes/seed.toml at 1280x720 with 9 rays per pixel on both backends,
# in one run so the ratio means something on a shared, noisy machine. Prints wall time,
# rays/s and peak memory per backend and the GPU/CPU speed ratio.
#
#   bench/seed.sh [runs=3]      (builds first with ./setup.sh build if build/lancer is missing)
set -euo pipefail
cd "$(dirname "$0")/.."
runs="${1:-3}"
[ -x build/lancer ] || ./setup.sh build
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# One warm-up GPU render fills Mesa's shader cache, so timings exclude the one-time JIT.
./build/lancer render scenes/seed.toml --width 64 --height 36 -q -o "$out/warm.png"

source bench/machine.sh
machine_description
echo

printf '%-8s %8s %10s %12s %10s\n' backend run seconds Mrays/s "peak MiB"
declare -A best
for run in $(seq 1 "$runs"); do
  for backend in gpu cpu; do   # interleaved, so drift hits both alike
    line=$(./build/lancer render scenes/seed.toml --width 1280 --height 720 --samples 3 \
             --backend "$backend" -o "$out/$backend.png" 2>&1 | tail -n 1)
    secs=$(sed -E 's/.*: ([0-9.]+) s, .*/\1/' <<<"$line")
    mrays=$(sed -E 's/.* ([0-9.]+) Mrays\/s.*/\1/' <<<"$line")
    rss=$(sed -E 's/.*peak RSS ([0-9]+) MiB.*/\1/' <<<"$line")
    printf '%-8s %8s %10s %12s %10s\n' "$backend" "$run" "$secs" "$mrays" "$rss"
    if [ -z "${best[$backend]:-}" ] || awk "BEGIN{exit !($secs < ${best[$backend]})}"; then best[$backend]=$secs; fi
  done
done
awk -v g="${best[gpu]}" -v c="${best[cpu]}" \
  'BEGIN{printf "best of %d: gpu %.3f s, cpu %.3f s; gpu is %.2fx the speed of the cpu reference\n", '"$runs"', g, c, c/g}'
