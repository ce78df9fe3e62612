#!/usr/bin/env bash
# Photon mapping against POV-Ray 3.7's (a benchmark, never a test: speed is not asserted).
#
#   bench/photons.sh [backend...]        (default: cpu gpu)
#
# The scene is bench/photons.toml: a glass ball's shadow and the caustic it focuses into it;
# POV-Ray renders its hand-written twin bench/pov/photons.pov (same camera, light, glass, floor).
# Both at 320x240, 4 rays per pixel (POV: +A0.0 +AM1 +R2), all in one run so the ratios mean
# something on a shared machine. It measures
#   1. photons per second: lancer shooting 1,000,000 photons into a 16x12 picture minus 1,000
#      (start-up, the picture and the kd-tree or grid build included), and POV-Ray's
#      "Number of photons shot" over its "Photon Time";
#   2. time to a noise level: each renderer's PSNR against its own long reference (lancer: 512
#      passes of 100,000 photons; POV-Ray: 8,000,000 photons) as its effort grows (lancer:
#      passes; POV-Ray: photons), and the wall time at which it first reaches TARGET_DB (30 dB
#      by default), interpolated in log time between the two efforts around it.
# Prints the CPU model and its vector extensions (lscpu) first. Images land in bench/out/photons/.
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

lscpu | grep -E '^(Model name|CPU\(s\)|Flags)' | sed -E 's/^Flags: +/Flags: /' |
  awk '/^Flags/ { n = split($0, f, " "); s = "Vector extensions:"; for (i = 2; i <= n; ++i)
         if (f[i] ~ /^(sse|ssse|avx|fma|f16c)/) s = s " " f[i]; print s; next } { print }'
echo

now() { date +%s.%N; }
wall() {  # seconds a command takes, its output discarded
  local t0; t0=$(now)
  "$@" >/dev/null 2>&1
  awk -v a="$t0" -v b="$(now)" 'BEGIN { printf "%.3f", b - a }'
}
lancer() {  # backend passes photons width height output
  build/lancer render bench/photons.toml --backend "$1" --passes "$2" --photons "$3" --width "$4" --height "$5" -q -o "$6"
}
pov() {  # photons width height output
  povray +Ibench/pov/photons.pov +O"$4" +W"$2" +H"$3" +A0.0 +AM1 +R2 -J +WT2 -D +FN Declare=PHOTONS="$1"
}
psnr() { build/lancer diff "$1" "$2" | sed -E 's/.*PSNR ([0-9.inf]+) dB.*/\1/'; }

echo "## Photons per second"
echo
echo "| renderer | photons/s |"
echo "|---|---|"
for b in "${backends[@]}"; do
  lancer "$b" 1 1000 16 12 "$out/warm.png" >/dev/null 2>&1  # warm-up: Mesa's shader cache
  t_small=$(wall lancer "$b" 1 1000 16 12 "$out/warm.png")
  t_big=$(wall lancer "$b" 1 1000000 16 12 "$out/warm.png")
  awk -v a="$t_small" -v b="$t_big" -v name="lancer $b" 'BEGIN { printf "| %s | %.0f |\n", name, 999000 / (b - a) }'
done
log=$(mktemp)
pov 1000000 16 12 "$out/warm.png" >"$log" 2>&1
shot=$(sed -nE 's/^Number of photons shot: *([0-9]+).*/\1/p' "$log" | tail -n 1)
secs=$(sed -nE 's/.*Photon Time:.*\(([0-9.]+) seconds\).*/\1/p' "$log" | tail -n 1)
awk -v n="$shot" -v t="$secs" 'BEGIN { printf "| POV-Ray 3.7 (%d photons shot in %.2f s; its photon pass is single-threaded) | %.0f |\n", n, t, n / t }'
rm -f "$log"
echo

# The time at which a sequence of "seconds psnr" lines first reaches the target, interpolated in
# log time between the two points around it; "-" if it never does.
reach() {
  awk -v target="$target" '{ t[NR] = $1; p[NR] = $2 }
    END { for (i = 1; i <= NR; ++i) if (p[i] >= target) {
            if (i == 1) { printf "%.2f", t[1]; exit }
            f = (target - p[i-1]) / (p[i] - p[i-1]);
            printf "%.2f", exp(log(t[i-1]) + f * (log(t[i]) - log(t[i-1]))); exit }
          print "-" }'
}

echo "## Time to ${target} dB against each renderer's own long reference"
echo
results=()
for b in "${backends[@]}"; do
  echo "lancer $b: reference (512 passes)..." >&2
  lancer "$b" 512 100000 320 240 "$out/lancer-$b-reference.png"
  : >"$out/lancer-$b.txt"
  for passes in 1 2 4 8 16 32 64; do
    t=$(wall lancer "$b" "$passes" 100000 320 240 "$out/lancer-$b-$passes.png")
    echo "$t $(psnr "$out/lancer-$b-$passes.png" "$out/lancer-$b-reference.png") $passes passes" >>"$out/lancer-$b.txt"
  done
  results+=("lancer $b|$(reach <"$out/lancer-$b.txt")|$out/lancer-$b.txt")
done
echo "POV-Ray: reference (8,000,000 photons)..." >&2
pov 8000000 320 240 "$out/pov-reference.png" >/dev/null 2>&1
: >"$out/pov.txt"
for photons in 25000 50000 100000 200000 400000 800000 1600000; do
  t=$(wall pov "$photons" 320 240 "$out/pov-$photons.png")
  echo "$t $(psnr "$out/pov-$photons.png" "$out/pov-reference.png") $photons photons" >>"$out/pov.txt"
done
results+=("POV-Ray 3.7, 2 threads|$(reach <"$out/pov.txt")|$out/pov.txt")

echo "| renderer | seconds to ${target} dB | effort: wall s, PSNR dB |"
echo "|---|---|---|"
for r in "${results[@]}"; do
  IFS='|' read -r name secs file <<<"$r"
  echo "| $name | $secs | $(awk '{ printf "%s%s: %.1f s, %.1f dB", (NR > 1 ? "; " : ""), $3 " " $4, $1, $2 }' "$file") |"
done
echo
echo "lancer's picture against POV-Ray's, both references (side by side: $out/side.png):"
build/lancer diff "$out/lancer-${backends[0]}-reference.png" "$out/pov-reference.png" --side-by-side "$out/side.png"
