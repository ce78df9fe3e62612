#!/usr/bin/env bash
# lancer's benchmark suite against POV-Ray 3.7 (a benchmark, never a test: speed is not asserted).
#
#   bench/run.sh [runs=3] [all|classic|implicit|quality|parametric|mesh|shapes|solids]
#
# For each suite scene, in one run so the ratios mean something on a shared, noisy machine:
# lancer on the GPU path (lavapipe here), lancer's CPU reference, and POV-Ray rendering the same
# scene (converted by bench/toml_to_pov.py), each after a warm-up, the median of `runs` runs.
# Columns: wall time of the whole process, render time alone (lancer's final line; POV's
# "Trace Time"), rays per second of render time (all rays: camera, shadow, reflection; POV's
# "Rays" plus "Shadow Ray Tests"), peak memory, and POV's wall time over this one's.
# POV-Ray renders the twins kept in bench/pov/ (checked against the converter first). Images
# land in bench/out/: SCENE-lancer.png, SCENE-pov.png and SCENE-side.png (lancer | POV |
# difference x 8) with their PSNR, so anyone can see they are the same picture.
#
# The implicit surfaces are set against two POV-Ray twins each: the exact `polynomial` (Sturm
# sequences, clipped to the same box) where the function is a polynomial, and the `isosurface`
# (Lipschitz subdivision: accuracy, and max_gradient measured over the box by the converter),
# with PSNRs against the exact picture (POV's polynomial; for the gyroid, lancer's CPU reference).
#
# Quality per time (suite `quality`): for seed, many, teapot and glass, each renderer's long
# reference (an 8 x 8 grid per pixel), then its full 3 x 3 grid and its adaptive anti-aliasing at
# POV-Ray's default threshold (+A0.3 +AM1 +R3; lancer --aa-threshold 0.3), each with its wall
# time, camera rays per pixel and PSNR against its own reference: what the picture costs to
# within a given quality, whatever the two renderers' small differences of picture.
#
# The parametric torus against POV-Ray's `parametric` (suite `parametric`, not in `all`): at the
# issue's 1280x720, where POV-Ray takes about 45 minutes (2 threads) and lancer's start-up no longer
# dominates; `classic` keeps the same comparison at 160x90, where lancer's time is mostly start-up.
#
# Meshes (suite `mesh`, not in `all`): the Stanford bunny (bench/bunny.toml, 69,451 triangles from
# ../shared/models beside the repository) and a torus knot of 10^6 triangles in the same view
# (bench/knot_million.toml, made by scenes/tools/make_meshes.py --million), against POV-Ray's
# mesh2 twins, which bench/toml_to_pov.py writes into bench/out/ (too large to keep).
#
# The shapes people build with (suite `shapes`, not in `all`): bench/shapes.toml (cylinder, cone,
# disc, torus, a CSG die, a superellipsoid and a blob, opaque) against the POV-Ray twin that
# bench/toml_to_pov.py writes into bench/out/.
#
# Solids of the solids issue (suite `solids`, not in `all`): a blob of thousands of components
# (bench/make_blob_field.py's rippled pool of 4,900 sphere components and a crown of 72 droplets,
# written into bench/out/), scenes/chess.toml (surfaces of revolution, CSG over them) and
# bench/extrusions.toml (prisms of each spline and a conic sweep, lathes, text), against their
# POV-Ray twins (bench/toml_to_pov.py).
#
# Installs POV-Ray (and GNU time) with apt-get when missing: the benchmark's own setup, not the
# main one.
set -euo pipefail
cd "$(dirname "$0")/.."
runs="${1:-3}"
suite="${2:-all}"
out=bench/out
mkdir -p "$out"

need=()
command -v povray >/dev/null || need+=(povray)
[ -x /usr/bin/time ] || need+=(time)
command -v python3 >/dev/null || need+=(python3)
if ((${#need[@]})); then
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${need[@]}" >/dev/null
fi
[ -x build/lancer ] || ./setup.sh build

source bench/machine.sh
machine_description
echo

median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }

# One timed run: prints "wall render rays peak_mib" (render and rays may be "-").
run_lancer() {  # scene width height backend
  local log; log=$(mktemp)
  /usr/bin/time -f "%e %M" -o "$log.time" build/lancer render "$1" --width "$2" --height "$3" --backend "$4" \
    -o "$out/$(basename "$1" .toml)-lancer-$4.png" 2>"$log"
  local line; line=$(grep "Mrays/s" "$log" | tail -n 1)
  local render rays; render=$(sed -E 's/.*: ([0-9.]+) s, .*/\1/' <<<"$line")
  rays=$(sed -E 's/.*\(([0-9.]+) M rays\).*/\1/' <<<"$line")
  read -r wall kib <"$log.time"
  echo "$wall $render $(awk -v r="$rays" 'BEGIN{print r*1e6}') $((kib / 1024))"
  rm -f "$log" "$log.time"
}

run_pov() {  # pov width height name
  local log; log=$(mktemp)
  /usr/bin/time -f "%e %M" -o "$log.time" povray +I"$1" +O"$out/$4-pov.png" +W"$2" +H"$3" \
    +A0.0 +AM1 +R3 -J +WT2 -D +FN >"$log" 2>&1
  local render rays shadow
  render=$(sed -nE 's/.*Trace Time:.*\(([0-9.]+) seconds\).*/\1/p' "$log" | tail -n 1)
  rays=$(sed -nE 's/^Rays: *([0-9]+).*/\1/p' "$log" | tail -n 1)
  shadow=$(sed -nE 's/^Shadow Ray Tests: *([0-9]+).*/\1/p' "$log" | tail -n 1)
  read -r wall kib <"$log.time"
  echo "$wall $render $((rays + ${shadow:-0})) $((kib / 1024))"
  rm -f "$log" "$log.time"
}

# One timed run of lancer with options, the image to $out/NAME.png: "wall camera_rays_per_pixel".
run_lancer_as() {  # name scene width height options...
  local name=$1 scene=$2 w=$3 h=$4 log; log=$(mktemp)
  shift 4
  /usr/bin/time -f "%e" -o "$log.time" build/lancer render "$scene" --width "$w" --height "$h" "$@" \
    -o "$out/$name.png" 2>"$log"
  local spp; spp=$(grep "Mrays/s" "$log" | tail -n 1 | sed -E 's/.*, ([0-9.]+) rays\/pixel.*/\1/')
  echo "$(cat "$log.time") $spp"
  rm -f "$log" "$log.time"
}

# The same for POV-Ray: "wall camera_rays_per_pixel". Its statistics count "Pixels" (a first ray
# each, an extra row included) and "Samples" (the anti-aliasing's further rays).
run_pov_as() {  # name pov width height options...
  local name=$1 pov=$2 w=$3 h=$4 log; log=$(mktemp)
  shift 4
  /usr/bin/time -f "%e" -o "$log.time" povray +I"$pov" +O"$out/$name.png" +W"$w" +H"$h" "$@" -J +WT2 -D +FN \
    >"$log" 2>&1
  local pixels samples
  pixels=$(sed -nE 's/^Pixels: *([0-9]+) .*/\1/p' "$log" | tail -n 1)
  samples=$(sed -nE 's/.*Samples: *([0-9]+) .*/\1/p' "$log" | tail -n 1)
  echo "$(cat "$log.time") $(awk -v p="${pixels:-0}" -v s="${samples:-0}" -v n=$((w * h)) 'BEGIN{printf "%.2f", (p + s) / n}')"
  rm -f "$log" "$log.time"
}

# Median over `runs` of a runner's lines, column by column.
measure() {
  local lines=()
  for _ in $(seq 1 "$runs"); do lines+=("$("$@")"); done
  local cols=()
  for c in 1 2 3 4; do cols+=("$(printf '%s\n' "${lines[@]}" | awk -v c="$c" '{print $c}' | median)"); done
  echo "${cols[*]}"
}

row() {  # scene size spp name "wall render rays mib" pov_wall
  read -r wall render rays mib <<<"$5"
  local mrays ratio
  mrays=$(awk -v r="$rays" -v t="$render" 'BEGIN{ if (t > 0) printf "%.2f", r / t / 1e6; else print "-" }')
  ratio=$(awk -v p="$6" -v w="$wall" 'BEGIN{ if (p == "-") print "-"; else printf "%.2f", p / w }')
  printf '| %s | %s | %s | %s | %s | %s | %s | %s | %s |\n' "$1" "$2" "$3" "$4" "$wall" "$render" "$mrays" "$mib" "$ratio"
}

# The POV-Ray twins are kept in bench/pov/ (torus: one per torus form; implicit surfaces: -poly
# and -isosurface); they must be what the converter makes of the scene today, so that both
# renderers draw the same picture.
check_twin() {  # twin scene converter-options...
  local twin=$1 scene=$2
  shift 2
  python3 bench/toml_to_pov.py "$scene" "$@" >"$out/$(basename "$twin")"
  if ! cmp -s "$twin" "$out/$(basename "$twin")"; then
    echo "$twin is out of date with $scene: python3 bench/toml_to_pov.py $scene $* > $twin" >&2
    exit 1
  fi
  echo "$twin"
}
scene_file() {  # name: a shipped scene, or one kept in bench/
  if [ -f "scenes/$1.toml" ]; then echo "scenes/$1.toml"; else echo "bench/$1.toml"; fi
}
pov_twin() {  # name variant
  local twin=bench/pov/$1.pov
  [ "$1" = torus ] && twin=bench/pov/torus-$2.pov
  check_twin "$twin" "$(scene_file "$1")" --torus-as "$2"
}

bench_scene() {  # scene width height cpu_width cpu_height [pov_variant]
  local name=$1 w=$2 h=$3 cw=$4 ch=$5 variant=${6:-parametric}
  local toml pov
  toml=$(scene_file "$name")
  pov=$(pov_twin "$name" "$variant")
  build/lancer render "$toml" --width 64 --height 36 -q -o "$out/warm.png"  # warm-up: Mesa's shader cache
  povray +I"$pov" +O"$out/warm.png" +W64 +H36 -D +FN >/dev/null 2>&1 || true
  local gpu cpu pov
  gpu=$(measure run_lancer "$toml" "$w" "$h" gpu)
  pov=$(measure run_pov "$pov" "$w" "$h" "$name")
  local pov_wall; pov_wall=$(awk '{print $1}' <<<"$pov")
  row "$name" "${w}x$h" 9 "lancer gpu" "$gpu" "$pov_wall"
  if [ "$cw" = "$w" ]; then
    cpu=$(measure run_lancer "$toml" "$w" "$h" cpu)
    row "$name" "${w}x$h" 9 "lancer cpu reference" "$cpu" "$pov_wall"
  fi
  row "$name" "${w}x$h" "9 (+centre)" "POV-Ray 3.7, 2 threads" "$pov" "$pov_wall"
  cp "$out/$name-lancer-gpu.png" "$out/$name-lancer.png"
  build/lancer diff "$out/$name-lancer.png" "$out/$name-pov.png" --side-by-side "$out/$name-side.png" \
    | sed 's/^/    /' >>"$out/psnr.txt"
  if [ "$cw" != "$w" ]; then
    # The CPU reference's exact patch algebra is far too slow for the full size: a smaller image.
    cpu=$(measure run_lancer "$toml" "$cw" "$ch" cpu)
    row "$name" "${cw}x$ch" 9 "lancer cpu reference" "$cpu" "-"
  fi
}

# One scene's rows of the quality-per-time table; pov may be "" (no twin: only lancer's rows).
bench_quality() {  # scene width height pov [why there is no twin]
  local name=$1 w=$2 h=$3 pov=$4 toml=scenes/$1.toml
  build/lancer render "$toml" --width 64 --height 36 -q -o "$out/warm.png"  # warm-up: Mesa's shader cache
  quality_row() {  # renderer aa "wall spp" image reference
    read -r wall spp <<<"$3"
    local metric; metric=$(build/lancer diff "$4" "$5" | head -n 1)
    local db; db=$(sed -nE 's/.*PSNR ([0-9.inf]+) dB.*/\1/p' <<<"$metric")
    local off; off=$(sed -nE 's/.*dB, ([0-9.]+%) of pixels.*/\1/p' <<<"$metric")
    printf '| %s | %s | %s | %s | %s | %s | %s | %s |\n' "$name" "${w}x$h" "$1" "$2" "$wall" "$spp" "${db:-inf}" "${off:-0%}"
  }
  local ref full adaptive
  ref=$(run_lancer_as "$name-q-lancer-ref" "$toml" "$w" "$h" --samples 8)
  full=$(measure_q run_lancer_as "$name-q-lancer-full" "$toml" "$w" "$h")
  adaptive=$(measure_q run_lancer_as "$name-q-lancer-adaptive" "$toml" "$w" "$h" --aa-threshold 0.3)
  quality_row "lancer gpu" "8 x 8 (reference)" "$ref" "$out/$name-q-lancer-ref.png" "$out/$name-q-lancer-ref.png"
  quality_row "lancer gpu" "3 x 3" "$full" "$out/$name-q-lancer-full.png" "$out/$name-q-lancer-ref.png"
  quality_row "lancer gpu" "--aa-threshold 0.3" "$adaptive" "$out/$name-q-lancer-adaptive.png" "$out/$name-q-lancer-ref.png"
  if [ -z "$pov" ]; then
    printf '| %s | %s | POV-Ray | no twin: %s | - | - | - | - |\n' "$name" "${w}x$h" "$5"
    return
  fi
  povray +I"$pov" +O"$out/warm.png" +W64 +H36 -D +FN >/dev/null 2>&1 || true
  ref=$(run_pov_as "$name-q-pov-ref" "$pov" "$w" "$h" +A0.0 +AM1 +R8)
  full=$(measure_q run_pov_as "$name-q-pov-full" "$pov" "$w" "$h" +A0.0 +AM1 +R3)
  adaptive=$(measure_q run_pov_as "$name-q-pov-adaptive" "$pov" "$w" "$h" +A0.3 +AM1 +R3)
  quality_row "POV-Ray 3.7, 2 threads" "+A0.0 +R8 (reference)" "$ref" "$out/$name-q-pov-ref.png" "$out/$name-q-pov-ref.png"
  quality_row "POV-Ray 3.7, 2 threads" "+A0.0 +R3" "$full" "$out/$name-q-pov-full.png" "$out/$name-q-pov-ref.png"
  quality_row "POV-Ray 3.7, 2 threads" "+A0.3 +AM1 +R3" "$adaptive" "$out/$name-q-pov-adaptive.png" "$out/$name-q-pov-ref.png"
}
# Median over `runs` of "wall spp" lines (the rays per pixel are the same every run).
measure_q() {
  local walls=() spp=""
  for _ in $(seq 1 "$runs"); do
    local line; line=$("$@")
    walls+=("${line%% *}")
    spp=${line##* }
  done
  echo "$(printf '%s\n' "${walls[@]}" | median) $spp"
}

psnr() {  # a b label: one line of lancer diff's metric
  echo "    $3: $(build/lancer diff "$1" "$2" | head -n 1)" >>"$out/psnr.txt"
}

# An implicit surface: lancer's GPU path and CPU reference, POV-Ray's exact polynomial (when the
# function is one) and its isosurface at `accuracy`; the ratios are POV's isosurface over each.
bench_implicit() {  # scene width height accuracy
  local name=$1 w=$2 h=$3 accuracy=$4
  local toml=scenes/$name.toml poly="" iso
  if python3 bench/toml_to_pov.py "$toml" | grep "^polynomial" >/dev/null; then  # grep -q would break the pipe
    poly=$(check_twin "bench/pov/$name-poly.pov" "$toml")
  fi
  iso=$(check_twin "bench/pov/$name-isosurface.pov" "$toml" --implicit-as isosurface --accuracy "$accuracy")
  build/lancer render "$toml" --width 64 --height 36 -q -o "$out/warm.png"  # warm-up: Mesa's shader cache
  local gpu cpu p i
  gpu=$(measure run_lancer "$toml" "$w" "$h" gpu)
  cpu=$(measure run_lancer "$toml" "$w" "$h" cpu)
  i=$(measure run_pov "$iso" "$w" "$h" "$name-isosurface")
  local iso_wall; iso_wall=$(awk '{print $1}' <<<"$i")
  row "$name" "${w}x$h" 9 "lancer gpu" "$gpu" "$iso_wall"
  row "$name" "${w}x$h" 9 "lancer cpu reference" "$cpu" "$iso_wall"
  local exact=$out/$name-lancer-cpu.png
  echo "  $name (${w}x$h; POV isosurface accuracy $accuracy):" >>"$out/psnr.txt"
  if [ -n "$poly" ]; then
    p=$(measure run_pov "$poly" "$w" "$h" "$name-poly")
    row "$name" "${w}x$h" "9 (+centre)" "POV-Ray polynomial (exact, sturm)" "$p" "$iso_wall"
    exact=$out/$name-poly-pov.png
  fi
  row "$name" "${w}x$h" "9 (+centre)" "POV-Ray isosurface" "$i" "$iso_wall"
  psnr "$out/$name-lancer-gpu.png" "$exact" "lancer gpu vs $(basename "$exact" .png)"
  psnr "$out/$name-lancer-cpu.png" "$exact" "lancer cpu vs $(basename "$exact" .png)"
  psnr "$out/$name-isosurface-pov.png" "$exact" "POV isosurface vs $(basename "$exact" .png)"
  psnr "$out/$name-lancer-gpu.png" "$out/$name-lancer-cpu.png" "lancer gpu vs lancer cpu (exact roots)"
  if [ -n "$poly" ]; then
    # POV's anti-aliasing counts the pixel centre twice: its polynomial again, at exactly lancer's
    # 3 x 3 sample positions (bench/pov_supersample.py), so that sampling is not what differs.
    povray +I"$poly" +O"$out/$name-poly-pov-3x.png" +W$((3 * w)) +H$((3 * h)) -A +FN16 File_Gamma=1.0 +WT2 -D \
      >/dev/null 2>&1
    python3 bench/pov_supersample.py 3 "$out/$name-poly-pov-3x.png" "$out/$name-poly-pov-samples.png"
    psnr "$out/$name-lancer-gpu.png" "$out/$name-poly-pov-samples.png" "lancer gpu vs POV polynomial at lancer's samples"
    psnr "$out/$name-lancer-cpu.png" "$out/$name-poly-pov-samples.png" "lancer cpu vs POV polynomial at lancer's samples"
  fi
  build/lancer diff "$out/$name-lancer-gpu.png" "$exact" --side-by-side "$out/$name-side.png" >/dev/null
}

: >"$out/psnr.txt"
if [ "$suite" = all ] || [ "$suite" = classic ]; then
  printf '| scene | size | rays/pixel | renderer | wall s | render s | Mrays/s | peak MiB | POV wall / this |\n'
  printf '|---|---|---|---|---|---|---|---|---|\n'
  bench_scene seed 1280 720 1280 720
  bench_scene many 1280 720 1280 720
  bench_scene teapot 1280 720 320 180
  bench_scene torus 1280 720 320 180 analytic
  # The same torus as lancer's exact `torus` shape, against POV-Ray's `torus` (bench/torus_shape.toml).
  bench_scene torus_shape 1280 720 1280 720
  # POV-Ray's parametric (Lipschitz subdivision) needs minutes for even a small torus image.
  bench_scene torus 160 90 160 90 parametric
fi
if [ "$suite" = mesh ] || [ "$suite" = shapes ] || [ "$suite" = solids ]; then
  [ "$suite" = mesh ] && { [ -f bench/out/torus_knot_million.obj ] || python3 scenes/tools/make_meshes.py --million; }
  names="bunny knot_million"
  [ "$suite" = shapes ] && names=shapes
  if [ "$suite" = solids ]; then
    python3 bench/make_blob_field.py >"$out/blob_field.toml"
    names="out/blob_field ../scenes/chess extrusions"
  fi
  printf '| scene | size | rays/pixel | renderer | wall s | render s | Mrays/s | peak MiB | POV wall / this |\n'
  printf '|---|---|---|---|---|---|---|---|---|\n'
  for path in $names; do
    name=$(basename "$path")
    python3 bench/toml_to_pov.py "bench/$path.toml" >"$out/$name.pov"
    build/lancer render "bench/$path.toml" --width 64 --height 36 -q -o "$out/warm.png"
    gpu=$(measure run_lancer "bench/$path.toml" 1280 720 gpu)
    cpu=$(measure run_lancer "bench/$path.toml" 1280 720 cpu)
    pov=$(measure run_pov "$out/$name.pov" 1280 720 "$name")
    pov_wall=$(awk '{print $1}' <<<"$pov")
    row "$name" 1280x720 9 "lancer gpu" "$gpu" "$pov_wall"
    row "$name" 1280x720 9 "lancer cpu reference" "$cpu" "$pov_wall"
    row "$name" 1280x720 "9 (+centre)" "POV-Ray 3.7, 2 threads" "$pov" "$pov_wall"
    build/lancer diff "$out/$name-lancer-gpu.png" "$out/$name-pov.png" --side-by-side "$out/$name-side.png" \
      | sed 's/^/    /' >>"$out/psnr.txt"
  done
  echo
  echo "Same pictures? (lancer vs POV-Ray; side by side in $out/*-side.png):"
  cat "$out/psnr.txt"
  exit 0
fi
if [ "$suite" = parametric ]; then
  printf '| scene | size | rays/pixel | renderer | wall s | render s | Mrays/s | peak MiB | POV wall / this |\n'
  printf '|---|---|---|---|---|---|---|---|---|\n'
  bench_scene torus 1280 720 320 180 parametric
fi
if [ "$suite" = all ] || [ "$suite" = quality ]; then
  echo
  echo "Quality per time (each renderer against its own 8 x 8 reference; wall time, median of $runs):"
  echo
  printf '| scene | size | renderer | anti-aliasing | wall s | camera rays/pixel | PSNR dB | pixels > 4/255 off |\n'
  printf '|---|---|---|---|---|---|---|---|\n'
  for scene in seed many teapot; do
    bench_quality "$scene" 640 360 "$(pov_twin "$scene" parametric)"
  done
  bench_quality glass 640 360 "" "transmission and parametric surfaces of revolution are not translated"
fi
if [ "$suite" = quality ]; then exit 0; fi
if [ "$suite" = all ] || [ "$suite" = implicit ]; then
  echo
  printf '| scene | size | rays/pixel | renderer | wall s | render s | Mrays/s | peak MiB | POV isosurface wall / this |\n'
  printf '|---|---|---|---|---|---|---|---|---|\n'
  for scene in implicit roman kummer barth clebsch gyroid; do
    bench_implicit "$scene" 640 360 0.001
  done
fi

# Start-up: a 1x1 render is nearly all instance, device, pipeline and shader-cache lookup. The
# first run fills the caches (Mesa's, lancer's) if anything did not; then five warm runs.
startup_run() {
  { /usr/bin/time -f "%e" build/lancer render scenes/seed.toml --width 1 --height 1 -q -o "$out/warm.png"; } 2>&1 |
    tail -n 1
}
startup_run >/dev/null
startup=$(for i in 1 2 3 4 5; do startup_run; done | sort -n | tr '\n' ' ')
echo
echo "lancer start-up, caches warm (process for a 1x1 render of seed.toml: instance, device, pipeline), five runs: ${startup}s"
echo
echo "Same pictures? (lancer vs POV-Ray; side by side in $out/*-side.png):"
cat "$out/psnr.txt"
