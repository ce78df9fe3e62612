#!/usr/bin/env bash
# Benchmark (not a test): N random spheres in a 10-unit cube over a checkered plane, one light,
# 640x360, 1 ray/pixel (issue 44's table), whole process (load + render), wall time and peak RSS:
#   set   - one `type = "spheres"` object reading a binary PLY point set (docs/scene-format.md)
#   toml  - one [[object]] table per sphere (N <= 10^6: the text is 120 bytes a sphere)
#   pov   - POV-Ray 3.7 on the same spheres written as N sphere statements (skipped without povray)
# lancer's gpu and cpu backends for each lancer form. Runs are interleaved; the best of `runs`.
#   bench/million_spheres.sh [N=1000000] [runs=2] [forms="set toml pov"]
set -euo pipefail
cd "$(dirname "$0")/.."
n="${1:-1000000}" runs="${2:-2}" forms="${3:-set toml pov}"
[ -x build/lancer ] || ./setup.sh build
source bench/machine.sh
machine_description
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

radius=$(python3 -c "print(0.5 * 10 / $n ** (1 / 3))")
python3 scenes/tools/make_points.py --million "$n" "$out/points.ply"
stage() {
  printf '[render]\nwidth = 640\nheight = 360\nsamples = 1\n\n[camera]\neye = [0, 8, -22]\nlook_at = [0, 4, 0]\n\n'
  printf '[[light]]\nposition = [10, 30, -20]\n\n[material.floor]\nchecker = { colors = [[1, 1, 1], [0.3, 0.3, 0.3]], size = 1 }\n\n'
  printf '[material.ball]\ncolor = [0.8, 0.3, 0.2]\n\n[[object]]\ntype = "plane"\nnormal = [0, 1, 0]\npoint = [0, 0, 0]\nmaterial = "floor"\n\n'
}
{ stage; printf '[[object]]\ntype = "spheres"\nfile = "points.ply"\nradius = %s\nmaterial = "ball"\n' "$radius"; } > "$out/set.toml"
# The same floats as text, one table each; POV-Ray's twin by bench/toml_to_pov.py (the same view).
python3 - "$out" "$n" "$radius" <<'PY'
import struct, sys
out, n, r = sys.argv[1], int(sys.argv[2]), sys.argv[3]
data = open(f"{out}/points.ply", "rb").read()
body = data[data.index(b"end_header\n") + 11:]
with open(f"{out}/objects.toml", "w") as f:
    f.write("".join('[[object]]\ntype = "sphere"\nmaterial = "ball"\ncenter = [%.9g, %.9g, %.9g]\nradius = %s\n\n'
                    % (*struct.unpack_from("<fff", body, 12 * i), r) for i in range(n)))
PY
python3 bench/toml_to_pov.py "$out/set.toml" > "$out/scene.pov"
{ stage; cat "$out/objects.toml"; } > "$out/toml.toml"

measure() {  # label, command...: "label wall_s rss_MiB"
  local label=$1; shift
  /usr/bin/time -f "%e %M" -o "$out/time" "$@" >/dev/null 2>"$out/err" || { echo "$label failed: $(grep -v 'Command exited' "$out/err" | tail -n 1)"; return; }
  read -r wall rss < "$out/time"
  printf '%-10s %8.2f s %8d MiB\n' "$label" "$wall" $((rss / 1024))
}
echo "$n spheres, 640x360, 1 ray/pixel, whole process; best of $runs"
for run in $(seq "$runs"); do
  for form in $forms; do
    case $form in
      set|toml)
        for backend in gpu cpu; do
          measure "$form-$backend" build/lancer render "$out/$form.toml" --backend "$backend" -o "$out/$form-$backend.png" --force
        done ;;
      pov)
        command -v povray >/dev/null && measure "pov-2T" povray +W640 +H360 -A +WT2 -D +FN +I"$out/scene.pov" +O"$out/pov.png" ;;
    esac
  done
done | sort -k1,1 -k2,2n | awk '!seen[$1]++'
