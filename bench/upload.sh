#!/usr/bin/env bash
# Benchmark (not a test): what skipping unchanged GPU buffers saves per animation frame.
# A generated scene of N spheres is rendered at 1x1 pixel (so tracing costs ~nothing) twice:
#   camera  - only the camera orbits: the primitive buffer is the same every frame and is skipped
#   object  - one sphere also moves: all N primitives (64 bytes each) are re-uploaded every frame
# The difference per frame is the upload that skipping avoids, plus building the BVH again (a
# renderer keeps its last tree while the primitives' boxes stay the same). Both runs still pack
# the primitives every frame (that is how unchanged contents are recognised).
#
#   bench/upload.sh [spheres=100000] [frames=24]
set -euo pipefail
cd "$(dirname "$0")/.."
spheres="${1:-100000}" frames="${2:-24}"
[ -x build/lancer ] || ./setup.sh build
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# side x side grid of small spheres on the floor; the first one is named so it can move.
generate() {  # $1 = with object keyframes (0/1)
  awk -v n="$spheres" -v frames="$frames" -v moving="$1" 'BEGIN{
    side = int(sqrt(n)) + 1
    printf "[render]\nwidth = 1\nheight = 1\nsamples = 1\n\n[animation]\nframes = %d\ncyclic = true\n\n", frames
    printf "[animation.camera_orbit]\ncenter = [0, 0, 0]\nradius = %d\nheight = %d\n\n", side, side / 2
    if (moving) printf "[[animation.object]]\nobject = \"mover\"\nkeys = [{ time = 0, translate = [0, 0, 0] }, { time = 0.5, translate = [0, 3, 0] }]\n\n"
    printf "[camera]\neye = [0, 10, -10]\nlook_at = [0, 0, 0]\n\n[[light]]\nposition = [0, 100, 0]\n\n"
    for (i = 0; i < n; i++) {
      printf "[[object]]\n%stype = \"sphere\"\ncenter = [%d, 0.4, %d]\nradius = 0.4\n\n", (i == 0 ? "name = \"mover\"\n" : ""), i % side - side / 2, int(i / side) - side / 2
    }
  }'
}
generate 0 > "$out/camera.toml"
generate 1 > "$out/object.toml"

printf '%d spheres (%d KiB of primitives), %d frames at 1x1 pixel (tracing costs ~nothing), gpu\n' "$spheres" $((spheres * 64 / 1024)) "$frames"
printf '%-8s %12s %14s %16s\n' run start-up "first frame" "frames 2..N"
declare -A per
for run in 1 2; do   # interleaved, so machine noise hits both alike
  for kind in camera object; do
    line=$(./build/lancer render "$out/$kind.toml" --force -o "$out/${kind}_%03d.png" 2>&1 | tail -n 1)
    s=$(sed -E 's/.*start-up ([0-9.]+) s.*/\1/' <<<"$line")
    f=$(sed -E 's/.*first frame ([0-9.]+) s.*/\1/' <<<"$line")
    p=$(sed -E 's/.*then ([0-9.]+) s\/frame.*/\1/' <<<"$line")
    printf '%-8s %12s %14s %16s\n' "$kind" "$s" "$f" "$p"
    if [ -z "${per[$kind]:-}" ] || awk "BEGIN{exit !($p < ${per[$kind]})}"; then per[$kind]=$p; fi
  done
done
awk -v c="${per[camera]}" -v o="${per[object]}" -v n="$spheres" 'BEGIN{
  printf "best per frame: camera only %.4f s, object moving %.4f s: skipping saves %.4f s/frame (%.0f%%) for %d KiB\n",
         c, o, o - c, 100 * (o - c) / o, n * 64 / 1024
}'
