#!/usr/bin/env bash
# Benchmark (not a test): scenes/seed.toml at 1280x720, 9 rays per pixel, on lancer's GPU path
# and CPU reference beside the Embree anchor (../shared/anchors/embree-seed: the same picture
# traced by Embree 3, a yardstick of what this CPU can do; issue 47's target is lancer's GPU path
# within 2x of it). Runs are interleaved (anchor, gpu, cpu, anchor, ...) after a warm-up round;
# prints the medians of the whole process's wall time and of the render timers, and the ratios.
# The anchor is built from ../shared into bench/out/ (never copied into the repository); skipped
# with a note where its source or libembree-dev is missing.
#
#   bench/embree.sh [runs=7]
set -euo pipefail
cd "$(dirname "$0")/.."
runs="${1:-7}"
anchor_src=../shared/anchors/embree-seed
anchor_dir=bench/out/embree-seed
[ -x build/lancer ] || ./setup.sh build
if [ ! -f "$anchor_src/seed_embree.cpp" ]; then
  echo "Embree anchor: no $anchor_src beside the repository; skipped"; exit 0
fi
if [ ! -f /usr/include/embree3/rtcore.h ]; then
  echo "Embree anchor: needs apt-get install -y libembree-dev libstb-dev libdeflate-dev; skipped"; exit 0
fi
if [ ! -x "$anchor_dir/seed_embree" ] || [ "$anchor_src/seed_embree.cpp" -nt "$anchor_dir/seed_embree" ]; then
  mkdir -p "$anchor_dir"
  cp "$anchor_src/seed_embree.cpp" "$anchor_src/build.sh" "$anchor_dir/"
  sh "$anchor_dir/build.sh"
fi
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

source bench/machine.sh
machine_description
echo

median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
run() {  # name: appends "wall render" to $out/name
  local cmd
  case $1 in
    anchor) cmd=("$anchor_dir/seed_embree" -o "$out/anchor.png" -v) ;;
    gpu|cpu) cmd=(build/lancer render scenes/seed.toml --width 1280 --height 720 --samples 3 --backend "$1" -o "$out/$1.png") ;;
  esac
  /usr/bin/time -f "%e" -o "$out/time" "${cmd[@]}" >"$out/log" 2>&1
  local render
  if [ "$1" = anchor ]; then
    render=$(sed -nE 's/.*render ([0-9.]+) s.*/\1/p' "$out/log")
  else
    render=$(tail -n 1 "$out/log" | sed -E 's/.*: ([0-9.]+) s, .*/\1/')
  fi
  echo "$(cat "$out/time") $render" >>"$out/$1"
}
for name in anchor gpu cpu; do run "$name"; done  # warm-up: Mesa's shader cache, the page cache
rm -f "$out/anchor" "$out/gpu" "$out/cpu"
for _ in $(seq "$runs"); do
  for name in anchor gpu cpu; do run "$name"; done
done
printf '| seed 1280x720, 9 rays/pixel | wall s (median of %s) | render s | wall / anchor | render / anchor |\n' "$runs"
printf '|---|---|---|---|---|\n'
anchor_wall=$(awk '{print $1}' "$out/anchor" | median)
anchor_render=$(awk '{print $2}' "$out/anchor" | median)
for name in anchor gpu cpu; do
  wall=$(awk '{print $1}' "$out/$name" | median)
  render=$(awk '{print $2}' "$out/$name" | median)
  case $name in anchor) label="Embree anchor" ;; gpu) label="lancer gpu" ;; cpu) label="lancer cpu reference" ;; esac
  printf '| %s | %s | %s | %.2f | %.2f |\n' "$label" "$wall" "$render" \
    "$(awk -v a="$wall" -v b="$anchor_wall" 'BEGIN{print a / b}')" "$(awk -v a="$render" -v b="$anchor_render" 'BEGIN{print a / b}')"
done
echo
build/lancer diff "$out/gpu.png" "$out/anchor.png"
