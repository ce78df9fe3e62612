#!/usr/bin/env bash
# The porting check (a benchmark, never a test): POV-Ray 3.7's own example scenes, ported by hand
# to lancer with docs/scene-format.md, rendered by both at the port's size and anti-aliasing
# (POV-Ray +A0.0 +AM1 +R<samples>), each the median of `runs` runs after a warm-up. Prints each
# port's PSNR against POV-Ray's picture and both renderers' wall and render times; the pictures
# land in bench/out/port-NAME-{lancer,pov,side}.png.
#
#   bench/port_check.sh [runs=3] [NAME ...]     (default: every bench/port/*.toml)
#
# A port names its original on its first line: "# POV-Ray 3.7's DIR/FILE.pov (povray-examples)".
# Installs POV-Ray and its examples with apt-get when missing (the benchmark's own setup).
set -euo pipefail
cd "$(dirname "$0")/.."
runs="${1:-3}"
shift || true
examples=/usr/share/doc/povray/examples
out=bench/out
mkdir -p "$out"
need=()
command -v povray >/dev/null || need+=(povray)
[ -d "$examples" ] || need+=(povray-examples)
command -v /usr/bin/time >/dev/null || need+=(time)
if [ ${#need[@]} -gt 0 ]; then apt-get update -qq && apt-get install -y -qq "${need[@]}" >/dev/null; fi
[ -x build/lancer ] || ./setup.sh build
source bench/machine.sh
machine_description
echo

names=("$@")
if [ ${#names[@]} -eq 0 ]; then for f in bench/port/*.toml; do names+=("$(basename "$f" .toml)"); done; fi

median() { sort -g | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }'; }
setting() { sed -nE "/^\[render\]/,/^\[/ s/^$2 = ([0-9]+).*/\1/p" "$1" | head -n 1; }

printf "%-16s %8s %10s %10s %10s %10s %8s\n" port "PSNR dB" "lancer s" "render s" "POV s" "trace s" "POV/lancer"
for name in "${names[@]}"; do
  port=bench/port/$name.toml
  original=$(sed -nE "1s/^# POV-Ray 3.7's ([^ ]+\.pov).*/\1/p" "$port")
  [ -n "$original" ] || { echo "$port: its first line does not name its original" >&2; exit 2; }
  w=$(setting "$port" width); h=$(setting "$port" height); n=$(setting "$port" samples)
  lancer_walls=() lancer_renders=() pov_walls=() pov_traces=()
  for run in $(seq 0 "$runs"); do  # run 0 warms both up
    /usr/bin/time -f "%e" -o "$out/port.time" build/lancer render "$port" -o "$out/port-$name-lancer.png" >"$out/port.log" 2>&1
    if [ "$run" -gt 0 ]; then
      lancer_walls+=("$(cat "$out/port.time")")
      lancer_renders+=("$(sed -nE 's/.*\): ([0-9.]+) s,.*/\1/p' "$out/port.log" | tail -n 1)")
    fi
    /usr/bin/time -f "%e" -o "$out/port.time" povray +I"$examples/$original" +L"$(dirname "$examples/$original")" \
      +O"$out/port-$name-pov.png" +W"$w" +H"$h" +A0.0 +AM1 +R"${n:-3}" -J +WT2 -D +FN >"$out/port.log" 2>&1
    if [ "$run" -gt 0 ]; then
      pov_walls+=("$(cat "$out/port.time")")
      pov_traces+=("$(sed -nE 's/.*Trace Time:.*\(([0-9.]+) seconds\).*/\1/p' "$out/port.log" | tail -n 1)")
    fi
  done
  psnr=$(build/lancer diff "$out/port-$name-lancer.png" "$out/port-$name-pov.png" --side-by-side "$out/port-$name-side.png" |
         sed -nE 's/.*PSNR ([0-9.inf]+) dB.*/\1/p')
  lw=$(printf "%s\n" "${lancer_walls[@]}" | median); lr=$(printf "%s\n" "${lancer_renders[@]}" | median)
  pw=$(printf "%s\n" "${pov_walls[@]}" | median); pt=$(printf "%s\n" "${pov_traces[@]}" | median)
  printf "%-16s %8s %10s %10s %10s %10s %8.2f\n" "$name" "$psnr" "$lw" "$lr" "$pw" "$pt" "$(echo "$pw / $lw" | bc -l)"
done
