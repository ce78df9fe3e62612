#!/usr/bin/env bash
# Renders the photon-mapping passes of one still on several machines with GNU parallel over ssh,
# then combines them (see docs/farm.md).
#
#   docs/farm/render-passes-parallel.sh SCENE OUTPUT PASSES HOSTS [CHUNK]
#
#   SCENE    the scene file (with a [photons] table)
#   OUTPUT   the finished image: .png (tone-mapped as the scene says), .exr or .pfm
#   PASSES   the passes of the whole render (the scene's [photons] passes, or what --passes gives)
#   HOSTS    GNU parallel's --sshlogin list, e.g. "1/render1,1/render2,1/:"
#   CHUNK    passes per job (default 8)
#
# Every host must see this directory at the same path. Each job renders passes A-B into
# OUTPUT.parts/A-B.exr (written atomically); a part that exists is not rendered again, so running
# this again after a failure renders only what is missing. The environment may set LANCER (the
# lancer command on the hosts, default "lancer") and LANCER_ARGS (more render options, e.g.
# "--backend cpu"); parallel itself reads PARALLEL_SSH (the ssh command). lancer combine checks
# that the parts cover every pass exactly once and names what is missing otherwise.
set -euo pipefail
if (($# < 4)); then
  sed -n '2,20p' "$0" >&2
  exit 2
fi
scene=$1 output=$2 passes=$3 hosts=$4 chunk=${5:-8}
lancer=${LANCER:-lancer}
parts="$output.parts"
mkdir -p "$parts"

# One line per job that is still to do: "A-B", the passes it renders.
ranges() {
  for ((first = 0; first < passes; first += chunk)); do
    last=$((first + chunk - 1))
    ((last < passes)) || last=$((passes - 1))
    [ -f "$parts/$first-$last.exr" ] || echo "$first-$last"
  done
}

command=$(printf '%q render %q --passes %d -q %s' "$lancer" "$scene" "$passes" "${LANCER_ARGS:-}")
ranges | parallel --will-cite -S "$hosts" --workdir . --retries 3 --tag \
  "$command --pass-range {} -o $(printf '%q' "$parts")/{}.exr"

"$lancer" combine "$parts"/*.exr -o "$output"
