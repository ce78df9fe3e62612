#!/usr/bin/env bash
# Photon mapping against POV-Ray 3.7's (a benchmark, never a test: speed is not asserted).
#
#   bench/photons.sh [backend...]        (default: cpu gpu)
#   TARGET_DB=35 bench/photons.sh cpu    # another noise level
#
# The scene is bench/photons.toml: a glass ball's shadow and the caustic it focuses into it;
# POV-Ray renders its hand-written twin bench/pov/photons.pov (same camera, light, glass, floor,
# the same light paths; a fixed gather radius, so that its estimate converges as photons are
# added). Both at 320x240, 4 rays per pixel (POV: +A0.0 +AM1 +R2), all in one run so the
# ratios mean something on a shared machine. It measures
#   1. photons per second: lancer shooting 1,000,000 photons into a 16x12 picture minus 1,000
#      (start-up, the picture and the kd-tree or grid build included), and POV-Ray's
#      "Number of photons shot" over its "Photon Time" (the map's build included), each time the
#      least of 3 runs (one run's difference of two wall times is too noisy). lancer sends
#      its photons into the spot's whole cone, POV-Ray only towards the ball (about 2/5 of it):
#      a POV-Ray photon does more work on average;
#   2. time to a noise level: each renderer's PSNR against its own long reference as its effort
#      grows (lancer: 1 to 64 passes of 100,000 photons, against 512 passes with another photon
#      seed; POV-Ray: `count` 31,250 to 1,000,000, against 8,000,000: both references 8x the
#      largest effort), and the wall time of the whole process at which it first reaches
#      TARGET_DB (30 dB by default), interpolated in log time between the two efforts around it;
#   3. how far apart the pictures are: the PSNR between the long references.
# Prints the machine (bench/machine.sh) first. Images land in bench/out/photons/.
# Installs POV-Ray with apt-get when missing (the benchmark's own setup, not the main one).
set -euo pipefail
cd "$(dirname "$0")/.."
backends=("$@")
((${#backends[@]})) || backends=(cpu gpu)
target=${TARGET_DB:-30}
out=bench/out/photons
mkdir -p "$out"
command -v povray >/dev/null || { sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq povray time >/dev/null; }
[ -x build/lancer ] || ./setup.sh build

source bench/machine.sh
machine_description
echo "POV-Ray: $(povray --version 2>&1 | sed -nE 's/^POV-Ray ([0-9][^ ]*).*/\1/p' | head -n 1); date: $(date -u +%Y-%m-%d)"
echo

# The reference's photons come from another seed, so that the passes measured are not part of it.
sed -E 's/^\[photons\]$/[photons]\nseed = 1/' bench/photons.toml >"$out/reference.toml"

now() { date +%s.%N; }
wall() {  # seconds a command takes, its output discarded
  local t0; t0=$(now)
  "$@" >/dev/null 2>&1
  awk -v a="$t0" -v b="$(now)" 'BEGIN { printf "%.3f", b - a }'
}
lancer() {  # scene backend passes photons width height output
  build/lancer render "$1" --backend "$2" --passes "$3" --photons "$4" --width "$5" --height "$6" -q -o "$7"
}
pov() {  # count width height output
  povray +Ibench/pov/photons.pov +O"$4" +W"$2" +H"$3" +A0.0 +AM1 +R2 -J +WT2 -D +FN Declare=PHOTONS="$1"
}
psnr() { build/lancer diff "$1" "$2" | sed -E 's/.*PSNR ([0-9.inf]+) dB.*/\1/'; }
least() { sort -g | head -n 1; }

echo "## Photons per second"
echo
echo "| renderer | photons shot | seconds | photons/s |"
echo "|---|---|---|---|"
for b in "${backends[@]}"; do
  lancer bench/photons.toml "$b" 1 1000 16 12 "$out/warm.png" >/dev/null 2>&1  # warm-up: Mesa's shader cache
  t_small=$(for i in 1 2 3; do wall lancer bench/photons.toml "$b" 1 1000 16 12 "$out/warm.png"; echo; done | least)
  t_big=$(for i in 1 2 3; do wall lancer bench/photons.toml "$b" 1 1000000 16 12 "$out/warm.png"; echo; done | least)
  awk -v a="$t_small" -v b="$t_big" -v name="lancer $b" \
    'BEGIN { printf "| %s (1,000,000 less 1,000: wall time difference) | 999000 | %.2f | %.0f |\n", name, b - a, 999000 / (b - a) }'
done
log=$(mktemp)
secs=$(for i in 1 2 3; do
  pov 1000000 16 12 "$out/warm.png" >"$log" 2>&1
  sed -nE 's/.*Photon Time:.*\(([0-9.]+) seconds\).*/\1/p' "$log" | tail -n 1
done | least)
shot=$(sed -nE 's/^Number of photons shot: *([0-9]+).*/\1/p' "$log" | tail -n 1)
awk -v n="$shot" -v t="$secs" \
  'BEGIN { printf "| POV-Ray 3.7 (count 1,000,000: its Photon Time; one light and one target: one thread) | %d | %.2f | %.0f |\n", n, t, n / t }'
rm -f "$log"
echo

# The time at which a sequence of "seconds psnr" lines first reaches the target, interpolated in
# log time between the two points around it; "<= t" if the first point already does, "-" if none.
reach() {
  awk -v target="$target" '{ t[NR] = $1; p[NR] = $2 }
    END { for (i = 1; i <= NR; ++i) if (p[i] >= target) {
            if (i == 1) { printf "<= %.2f", t[1]; exit }
            f = (target - p[i-1]) / (p[i] - p[i-1]);
            printf "%.2f", exp(log(t[i-1]) + f * (log(t[i]) - log(t[i-1]))); exit }
          print "-" }'
}

results=()
for b in "${backends[@]}"; do
  echo "lancer $b: reference (512 passes, photon seed 1)..." >&2
  lancer "$out/reference.toml" "$b" 512 100000 320 240 "$out/lancer-$b-reference.png"
  : >"$out/lancer-$b.txt"
  for passes in 1 2 4 8 16 32 64; do
    t=$(wall lancer bench/photons.toml "$b" "$passes" 100000 320 240 "$out/lancer-$b-$passes.png")
    echo "$t $(psnr "$out/lancer-$b-$passes.png" "$out/lancer-$b-reference.png") $passes passes" >>"$out/lancer-$b.txt"
  done
  results+=("lancer $b|$(reach <"$out/lancer-$b.txt")|$out/lancer-$b.txt")
done
echo "POV-Ray: reference (count 8,000,000)..." >&2
pov 8000000 320 240 "$out/pov-reference.png" >/dev/null 2>&1
: >"$out/pov.txt"
for count in 31250 62500 125000 250000 500000 1000000; do
  t=$(wall pov "$count" 320 240 "$out/pov-$count.png")
  echo "$t $(psnr "$out/pov-$count.png" "$out/pov-reference.png") count $count" >>"$out/pov.txt"
done
results+=("POV-Ray 3.7, 2 threads|$(reach <"$out/pov.txt")|$out/pov.txt")

pov_secs=$(reach <"$out/pov.txt")
echo "## Time to ${target} dB against each renderer's own long reference (wall s of the whole process)"
echo
echo "| renderer | seconds to ${target} dB | POV-Ray's / this | effort: wall s, PSNR dB |"
echo "|---|---|---|---|"
for r in "${results[@]}"; do
  IFS='|' read -r name secs file <<<"$r"
  ratio=$(awk -v a="$pov_secs" -v b="$secs" 'BEGIN { if (a ~ /^[0-9.]+$/ && b ~ /^[0-9.]+$/) printf "%.1f", a / b; else print "-" }')
  echo "| $name | $secs | $ratio | $(awk '{ printf "%s%s: %.2f s, %.1f dB", (NR > 1 ? "; " : ""), $3 " " $4, $1, $2 }' "$file") |"
done
echo
echo "## The long references against each other (PSNR dB; side by side: $out/side-*.png)"
echo
echo "| A | B | PSNR dB |"
echo "|---|---|---|"
for b in "${backends[@]}"; do
  build/lancer diff "$out/lancer-$b-reference.png" "$out/pov-reference.png" --side-by-side "$out/side-$b-pov.png" >/dev/null
  echo "| lancer $b | POV-Ray | $(psnr "$out/lancer-$b-reference.png" "$out/pov-reference.png") |"
done
if ((${#backends[@]} > 1)); then
  echo "| lancer ${backends[0]} | lancer ${backends[1]} | $(psnr "$out/lancer-${backends[0]}-reference.png" "$out/lancer-${backends[1]}-reference.png") |"
fi
