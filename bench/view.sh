#!/usr/bin/env bash
# Benchmark (not a test): `lancer view` on scenes/seed.toml in a virtual X server, driven like a
# user: a key held down (30 camera moves, 50 ms apart: previews), then released (the view refines
# to full quality), three times; then Esc. The viewer's closing summary gives the median preview
# time and the resolution it settled on, the median refinement and pass times, the sRGB
# conversion, and what showing a picture costs (texture upload, draw and present), for each SDL
# renderer: 'opengl' (Mesa's llvmpipe under Xvfb) and 'software'.
#
#   bench/view.sh [width=640] [height=360]
#
# Needs Xvfb and xdotool (./setup.sh installs them). Builds first if build/lancer is missing.
set -euo pipefail
cd "$(dirname "$0")/.."
width="${1:-640}" height="${2:-360}"
[ -x build/lancer ] || ./setup.sh build
out=$(mktemp -d)
exec 3>"$out/display"
Xvfb -displayfd 3 -screen 0 1920x1200x24 -nolisten tcp 2>"$out/xvfb.log" &
xvfb=$!
trap 'kill $xvfb 2>/dev/null; rm -rf "$out"' EXIT
for _ in $(seq 100); do [ -s "$out/display" ] && break; sleep 0.1; done
export DISPLAY=":$(head -n 1 "$out/display")"

for renderer in opengl software; do
  log="$out/$renderer.log"
  SDL_RENDER_DRIVER=$renderer ./build/lancer view scenes/seed.toml --width "$width" --height "$height" \
      -o "$out/shot.png" 2>"$log" &
  viewer=$!
  refined() { local n; n=$(grep -c 'view: refined' "$log" 2>/dev/null); echo "${n:-0}"; }
  for _ in $(seq 600); do [ "$(refined)" -ge 1 ] && break; sleep 0.1; done
  window=$(xdotool search --sync --onlyvisible --class lancer | head -n 1)
  xdotool windowfocus --sync "$window" mousemove --window "$window" 5 5
  for round in 1 2 3; do
    xdotool key --delay 50 --repeat 30 Right
    for _ in $(seq 600); do [ "$(refined)" -ge $((round + 1)) ] && break; sleep 0.1; done
  done
  xdotool key Escape
  wait "$viewer"
  echo "SDL renderer '$renderer', ${width}x${height}:"
  grep -E 'view: refined' "$log" | tail -n 1 | sed -E 's/; camera:.*//; s/^/  /'
  tail -n 1 "$log" | sed "s/^/  /"
done
