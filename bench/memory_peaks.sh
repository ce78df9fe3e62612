#!/usr/bin/env bash
# Measurement (not a test): the peak address space (VmPeak) and resident memory (VmHWM) of a cold
# GPU render of each scene given, with one malloc arena as lancer keeps under an address-space
# limit, beside the need lancer's own check names. The figures behind
# MemoryLimits.TheRenderEstimateCoversTheMeasuredPeaksOfManyImplicitSurfaces come from this
# (docs/robustness.md, "Memory limits"); run it with VK_DRIVER_FILES set for another lavapipe.
#
#   bench/memory_peaks.sh SCENE.toml...
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/lancer ] || ./setup.sh build
source bench/machine.sh
machine_description
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
printf '| scene | check needs (MiB) | VmPeak (MiB) | VmHWM (MiB) | seconds |\n|---|---|---|---|---|\n'
for scene in "$@"; do
  # The check's figure: under a limit too small for anything, lancer names what it would need.
  need=$(LANCER_CACHE_DISABLE=1 prlimit --as=$((400 << 20)) build/lancer render "$scene" -o "$out/x.png" 2>&1 |
         grep -o 'raise it to at least [0-9]* MiB' | grep -o '[0-9]*' || echo "-")
  start=$SECONDS
  LANCER_CACHE_DISABLE=1 MALLOC_ARENA_MAX=1 build/lancer render "$scene" -q -o "$out/x.png" &
  pid=$! peak=0 hwm=0
  while kill -0 "$pid" 2>/dev/null; do
    read -r p h < <(awk '/VmPeak/{p=$2} /VmHWM/{h=$2} END{print p+0, h+0}' "/proc/$pid/status" 2>/dev/null || echo "0 0")
    ((p > peak)) && peak=$p
    ((h > hwm)) && hwm=$h
    sleep 0.1
  done
  wait "$pid"
  printf '| %s | %s | %d | %d | %d |\n' "$(basename "$scene")" "$need" $((peak / 1024)) $((hwm / 1024)) $((SECONDS - start))
done
