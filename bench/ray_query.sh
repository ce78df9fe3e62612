#!/usr/bin/env bash
# The driver's ray queries (VK_KHR_acceleration_structure + VK_KHR_ray_query, built and traced by
# the Vulkan driver) against lancer's own BVH, on lavapipe (a benchmark, never a test; issue 44):
#
#   bench/ray_query.sh [runs=3] [bunny|knot|field ...]
#   bench/ray_query.sh --validate      # the bunny once under the Khronos validation layer
#
# Workloads: the Stanford bunny (bench/ray_query_bunny.toml, 69,451 triangles from
# ../shared/models), the torus knot of 10^6 triangles (bench/ray_query_knot.toml; made by
# scenes/tools/make_meshes.py --million) and 10^4 instances of the bunny (bench/make_bunny_field.py
# --matte): flat, matte, one point light, no floor, so that both sides do the same work, one
# camera ray per pixel at 1280x720 and one shadow ray to the light.
# build/bench/lancer_ray_query does each workload's runs interleaved in one process (lancer's
# build and render, the driver's build and trace; ray_query.cpp says how each is timed) and
# prints their medians; the driver is given the triangles and instances twice: in the scene's
# order, and in the order of lancer's trees' leaves (Mesa 25.0's lavapipe halves them in the
# order given). Between them this script times `build/lancer render SCENE --samples 1` (its
# render timer: preparation included). Pictures land in bench/out/ray_query-*.png, compared
# by `lancer diff`.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${BUILD:-build}"
out=bench/out
mkdir -p "$out"
for program in "$build/lancer" "$build/bench/lancer_ray_query"; do
  [ -x "$program" ] || { echo "ray_query.sh: $program is missing: build it first (ninja -C $build lancer lancer_ray_query)" >&2; exit 2; }
done
[ -f ../shared/models/stanford-bunny.obj ] || { echo "ray_query.sh: ../shared/models/stanford-bunny.obj is missing" >&2; exit 2; }

if [ "${1:-}" = "--validate" ]; then
  LANCER_VALIDATION=1 "$build/bench/lancer_ray_query" bench/ray_query_bunny.toml "$out/ray_query-valid-driver.png" \
    "$out/ray_query-valid-lancer.png" 1
  echo "no validation message (the program exits 1 on any)"
  exit 0
fi

runs="${1:-3}"
shift || true
workloads=("${@:-bunny knot field}")
read -r -a workloads <<< "${workloads[*]}"

scene_of() {
  case "$1" in
    bunny) echo bench/ray_query_bunny.toml ;;
    knot)
      [ -f "$out/torus_knot_million.obj" ] || python3 scenes/tools/make_meshes.py --million >&2
      echo bench/ray_query_knot.toml ;;
    field)
      [ -f "$out/bunny_field_matte.toml" ] || python3 bench/make_bunny_field.py 10000 --matte >&2
      echo "$out/bunny_field_matte.toml" ;;
    *) echo "ray_query.sh: unknown workload '$1' (bunny, knot, field)" >&2; exit 2 ;;
  esac
}

median() { sort -g | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
# The value of key=VALUE on the program's "result" lines.
field_of() { grep -o "$2=[^ ]*" "$1" | head -n 1 | cut -d= -f2; }
mib() { awk -v b="$1" 'BEGIN { printf "%.1f MiB", b / 1048576 }'; }
ms() { awk -v s="$1" 'BEGIN { printf "%.0f ms", s * 1000 }'; }

source bench/machine.sh
machine_description
echo "lavapipe: $(vulkaninfo 2>/dev/null | sed -nE 's/^[[:space:]]*driverInfo[[:space:]]*= *//p' | head -n 1)"
echo "runs: $runs per workload (medians)"
echo

rows=()
for w in "${workloads[@]}"; do
  scene=$(scene_of "$w")
  log="$out/ray_query-$w.log"
  cli_times=()
  # The command line's render first and after, around the interleaved runs in one process.
  for ((r = 1; r <= runs; r++)); do
    line=$("$build/lancer" render "$scene" --samples 1 -o "$out/ray_query-$w-cli.png" 2>&1 | tail -n 1)
    cli_times+=("$(sed -nE 's/.*: ([0-9.]+) s, .*/\1/p' <<< "$line")")
    if ((r == 1)); then
      # 10^4 instances of the bunny in its file's order: one trace ran over 5 minutes, not measured.
      order=""; [ "$w" = field ] && order=sorted-only
      "$build/bench/lancer_ray_query" "$scene" "$out/ray_query-$w-driver.png" "$out/ray_query-$w-lancer.png" "$runs" $order | tee "$log"
    fi
  done
  cli=$(printf '%s\n' "${cli_times[@]}" | median)
  echo "lancer render --samples 1 (command line, render timer, preparation included): ${cli_times[*]} s; median $cli s"
  "$build/lancer" diff "$out/ray_query-$w-driver.png" "$out/ray_query-$w-lancer.png" --side-by-side "$out/ray_query-$w-side.png"
  "$build/lancer" diff "$out/ray_query-$w-driver.png" "$out/ray_query-$w-cli.png"
  echo
  lb=$(field_of "$log" lancer_build); lt=$(field_of "$log" lancer_trace); lbytes=$(field_of "$log" lancer_bytes)
  for path in driver driver_sorted; do
    grep -q "${path}_build=" "$log" || continue
    db=$(field_of "$log" "${path}_build"); dt=$(field_of "$log" "${path}_trace")
    dbytes=$(field_of "$log" "${path}_bytes"); scratch=$(field_of "$log" "${path}_scratch")
    order="the scene's order"; [ "$path" = driver_sorted ] && order="lancer's order"
    ratio=$(awk -v d="$dt" -v l="$lt" 'BEGIN { printf "%.2f", d / l }')
    rows+=("| $w, driver given $order | $(ms "$lb") | $(ms "$db") | $(mib "$lbytes") | $(mib "$dbytes") (+ $scratch B scratch) | $(ms "$lt") | $(ms "$dt") | $ratio | $(ms "$cli") |")
  done
done

echo "| workload | lancer BVH build | driver build | lancer bytes | driver bytes | lancer trace | driver trace | ratio (driver / lancer trace) | lancer render (command line) |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|"
printf '%s\n' "${rows[@]}"
