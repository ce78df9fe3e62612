#!/usr/bin/env bash
# Before/after benchmark (not a test): every scene in scenes/ rendered by two lancer
# executables, alternating per run so that drift on a shared machine hits both alike, on the GPU
# path. Prints one Markdown row per scene: the medians of the render time (lancer's final line)
# and of the user CPU time (less sensitive to other load), the ratio after/before, and whether
# the two PNGs are byte-identical. Animated scenes render their first frame.
#
#   bench/every_scene.sh [-n runs=3] [-s WxH=320x180] BEFORE AFTER
#   bench/every_scene.sh /tmp/lancer-ac41e82 build/lancer
#   LANCER_SCENES="scenes/seed.toml scenes/many.toml" bench/every_scene.sh ...   # some scenes only
#   bench/every_scene.sh "env VK_DRIVER_FILES=build/mesa22/lvp_icd.json build/lancer" build/lancer
#                                         # one binary on two drivers (./setup.sh mesa22 unpacks 22.3)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=3
size=320x180
while getopts "n:s:" opt; do
  case $opt in
    n) runs=$OPTARG ;;
    s) size=$OPTARG ;;
    *) echo "usage: $0 [-n runs] [-s WxH] BEFORE AFTER" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[ $# -eq 2 ] || { echo "usage: $0 [-n runs] [-s WxH] BEFORE AFTER" >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

source bench/machine.sh
machine_description
echo "before: $1"
echo "after:  $2"
echo

median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }
run() {  # command scene png: prints "render user" (the command is split into words)
  local args=("$2" --width "${size%x*}" --height "${size#*x}")
  local animated=false
  grep -q '^\[animation\]' "$2" && animated=true
  if $animated; then args+=(--frames 0 -o "${3%.png}_%d.png"); else args+=(-o "$3"); fi
  # An animation's frame left from the last run would be resumed (skipped), not rendered.
  rm -f "${3%.png}_0.png"
  local command
  read -r -a command <<<"$1"
  /usr/bin/time -f "%U" -o "$out/time" "${command[@]}" render "${args[@]}" 2>"$out/log" >/dev/null
  if $animated; then mv "${3%.png}_0.png" "$3"; fi
  # The timing line (notes about re-rendered bands may follow it); an animation's frame line.
  local render
  render=$(grep -E 'frame 0 \(1/1\), [0-9.]+ s' "$out/log" | sed -E 's/.*, ([0-9.]+) s.*/\1/' || true)
  [ -n "$render" ] || render=$(grep 'Mrays/s' "$out/log" | tail -n 1 | sed -E 's/.*: ([0-9.]+) s, .*/\1/')
  echo "$render $(tail -n 1 "$out/time")"
}

echo "| scene ($size) | before render s | after render s | before user s | after user s | after/before (user) | same PNG |"
echo "|---|---|---|---|---|---|---|"
for scene in ${LANCER_SCENES:-scenes/*.toml}; do
  name=$(basename "$scene" .toml)
  rm -f "$out"/A* "$out"/B*
  run "$1" "$scene" "$out/a.png" >/dev/null && run "$2" "$scene" "$out/b.png" >/dev/null  # warm Mesa's cache
  for i in $(seq 1 "$runs"); do
    run "$1" "$scene" "$out/a.png" >>"$out/A"
    run "$2" "$scene" "$out/b.png" >>"$out/B"
  done
  ra=$(cut -d' ' -f1 "$out/A" | median); ua=$(cut -d' ' -f2 "$out/A" | median)
  rb=$(cut -d' ' -f1 "$out/B" | median); ub=$(cut -d' ' -f2 "$out/B" | median)
  same=no; cmp -s "$out/a.png" "$out/b.png" && same=yes
  awk -v n="$name" -v ra="$ra" -v rb="$rb" -v ua="$ua" -v ub="$ub" -v s="$same" \
    'BEGIN { printf "| %s | %.3f | %.3f | %.2f | %.2f | %.2f | %s |\n", n, ra, rb, ua, ub, ub / ua, s }'
done
