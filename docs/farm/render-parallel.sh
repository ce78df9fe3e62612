#!/usr/bin/env bash
# Renders an animation on several machines with GNU parallel over ssh (see docs/farm.md).
#
#   docs/farm/render-parallel.sh SCENE PATTERN FRAMES HOSTS [CHUNK]
#
#   SCENE    the scene file
#   PATTERN  where the frames go, e.g. frames/orbit_%03d.png
#   FRAMES   the animation's frame count (its [animation] frames)
#   HOSTS    GNU parallel's --sshlogin list: "1/render1,1/render2" runs one job at a time on
#            each of the two hosts (lavapipe already uses every core of a host); ":" is this machine
#   CHUNK    frames per job (default 10)
#
# Every host must see this directory at the same path (NFS or similar): jobs run in it, read
# SCENE and write the frames there. The environment may set LANCER (the lancer command on the
# hosts, default "lancer") and LANCER_ARGS (more render options, e.g. "--backend cpu"); parallel
# itself reads PARALLEL_SSH (the ssh command).
#
# Frames that exist are skipped and frames are written atomically, so running this again after
# a failure renders only what is missing. A failed job is retried, on another host if there is one.
# The exit status is 0 only if every frame exists at the end.
set -euo pipefail
if (($# < 4)); then
  sed -n '2,20p' "$0" >&2
  exit 2
fi
scene=$1 pattern=$2 frames=$3 hosts=$4 chunk=${5:-10}
lancer=${LANCER:-lancer}

# One line per job: "A-B", the frames it renders.
ranges() {
  for ((first = 0; first < frames; first += chunk)); do
    last=$((first + chunk - 1))
    ((last < frames)) || last=$((frames - 1))
    echo "$first-$last"
  done
}

# The command each job runs on its host, quoted for the remote shell.
command=$(printf '%q render %q -o %q -q %s --frames' "$lancer" "$scene" "$pattern" "${LANCER_ARGS:-}")
ranges | parallel --will-cite -S "$hosts" --workdir . --retries 3 --tag "$command {}"

# parallel's exit status covers the jobs it saw fail, not a host that ran nothing and said yes, so
# the frames themselves are the test of success. The pattern is lancer's (%d, %0Nd, %%): printf's.
missing=()
for ((k = 0; k < frames; ++k)); do
  printf -v frame -- "$pattern" "$k"
  [ -f "$frame" ] || missing+=("$frame")
done
if ((${#missing[@]})); then
  echo "render-parallel: ${#missing[@]} of $frames frames missing after every job ended, the first: ${missing[0]}" >&2
  exit 1
fi
