#!/usr/bin/env bash
# A/B benchmark (not a test): one scene rendered by two variants of lancer, alternating, so
# that drift on a shared machine hits both alike. A variant is a lancer executable, or a shader
# directory (rendered by build/lancer --shaders DIR). Prints each run, then the medians of wall
# time (as the render line reports it) and of user CPU time (less sensitive to other load),
# and the ratios B/A.
#
#   bench/ab.sh [-n runs=7] [-s WxH=1280x720] [-a 'RENDER ARGS'] SCENE A B
#   bench/ab.sh scenes/seed.toml /tmp/lancer-before build/lancer
#   bench/ab.sh -a '--aa-threshold 0.3' scenes/many.toml /tmp/lancer-before build/lancer
#   bench/ab.sh -s 16x9 scenes/seed.toml shaders/ /tmp/shaders-variant/   # start-up cost only
set -euo pipefail
cd "$(dirname "$0")/.."
runs=7
size=1280x720
extra=""
usage="usage: $0 [-n runs] [-s WxH] [-a 'RENDER ARGS'] SCENE A B"
while getopts "n:s:a:" opt; do
  case $opt in
    n) runs=$OPTARG ;;
    s) size=$OPTARG ;;
    a) extra=$OPTARG ;;
    *) echo "$usage" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[ $# -eq 3 ] || { echo "$usage" >&2; exit 2; }
scene=$1
[ -x build/lancer ] || ./setup.sh build
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

source bench/machine.sh
machine_description
echo

command_for() {  # the lancer command line of a variant
  if [ -d "$1" ]; then echo "build/lancer render --shaders $1"; else echo "$1 render"; fi
}
run() {  # prints "wall user" of one render
  local cmd; cmd=$(command_for "$1")
  # shellcheck disable=SC2086  # the extra arguments are split as on a command line
  /usr/bin/time -f "%U" -o "$out/time" $cmd "$scene" --width "${size%x*}" --height "${size#*x}" $extra \
    -o "$out/image.png" 2>"$out/log" >/dev/null
  local wall; wall=$(grep "Mrays/s" "$out/log" | tail -n 1 | sed -E 's/.*: ([0-9.]+) s, .*/\1/')
  echo "$wall $(tail -n 1 "$out/time")"
}

run "$2" >/dev/null; run "$3" >/dev/null   # warm Mesa's shader cache for both
printf '%-4s %4s %10s %10s\n' variant run "wall s" "user s"
for i in $(seq 1 "$runs"); do
  for v in A B; do
    if [ $v = A ]; then arg=$2; else arg=$3; fi
    read -r wall user < <(run "$arg")
    printf '%-4s %4s %10s %10s\n' "$v" "$i" "$wall" "$user"
    echo "$wall $user" >>"$out/$v"
  done
done
median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }
for v in A B; do
  w=$(cut -d' ' -f1 "$out/$v" | median); u=$(cut -d' ' -f2 "$out/$v" | median)
  eval "wall_$v=$w user_$v=$u"
done
awk -v wa="$wall_A" -v wb="$wall_B" -v ua="$user_A" -v ub="$user_B" -v n="$runs" 'BEGIN {
  printf "median of %d: A %.3f s wall, %.2f s user; B %.3f s wall, %.2f s user; B/A: wall %.3f, user %.3f\n",
         n, wa, ua, wb, ub, wb / wa, ub / ua }'
