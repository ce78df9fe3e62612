#!/usr/bin/env bash
# lancer's one entry point for a fresh Debian 12 machine (run as root, or with sudo available):
#
#   ./setup.sh render   install the packages, build, render scenes/seed.toml to seed.png
#   ./setup.sh test     install the packages, build, run the whole test suite
#   ./setup.sh build    install the packages and build only
#   ./setup.sh sanitize [CTEST ARGS] the asan preset (ASan + UBSan) in build-asan/, and the whole
#                       suite under it (or what the ctest arguments select, e.g. -LE render)
#   ./setup.sh fuzz [S] also clang: the fuzz targets in build-fuzz/, each run for S seconds (default 60)
#   ./setup.sh mesa22 [CTEST ARGS] the GPU tests again on Debian 12's own lavapipe (Mesa 22.3),
#                       unpacked into build/mesa22/ beside the Mesa 25 that lancer runs on
#
# Packages are installed only when one is missing, so re-running is quick.
set -euo pipefail
cd "$(dirname "$0")"

mode="${1:-build}"
case "$mode" in render|test|build|sanitize|fuzz|mesa22) ;; *) echo "usage: $0 render|test|build|sanitize [ctest args]|fuzz [seconds]|mesa22 [ctest args]" >&2; exit 2 ;; esac

# Every build and test dependency, all from Debian 12 (see DEVELOPERS.md for what each is for).
packages=(
  cmake ninja-build g++ pkg-config
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools
  glslang-dev glslang-tools spirv-tools
  libglm-dev libstb-dev libdeflate-dev liblapacke-dev libopenblas-dev libopenexr-dev libssl-dev
  libtomlplusplus-dev libcli11-dev libfmt-dev
  libfreetype-dev fonts-dejavu-core fonts-povray
  libgtest-dev libgmock-dev libbenchmark-dev
  ffmpeg
  libsdl2-dev xvfb xdotool x11-apps
  parallel
)
# The fuzzers need clang, its runtimes (ASan, UBSan, libFuzzer) and llvm-symbolizer for readable
# stack traces; the other builds use g++ (whose sanitizer runtimes come with it).
if [ "$mode" = fuzz ]; then packages+=(clang libclang-rt-14-dev llvm); fi

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
apt_install() { DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "$@" >/dev/null; }

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# lavapipe from Mesa 25 (Debian's bookworm-backports) renders in half the time of Debian 12's own
# Mesa 22.3 (docs/performance.md). Elsewhere than bookworm, the release's own Mesa is used.
mesa_wanted=25
mesa=$(dpkg-query -W -f='${Version}' mesa-vulkan-drivers 2>/dev/null || true)
backports=""
if [ -z "$mesa" ] || dpkg --compare-versions "$mesa" lt "$mesa_wanted"; then
  if grep -q '^VERSION_CODENAME=bookworm$' /etc/os-release 2>/dev/null; then
    backports=bookworm-backports
    if ! grep -rqs "bookworm-backports" /etc/apt/sources.list /etc/apt/sources.list.d/; then
      echo "setup: adding Debian's bookworm-backports to apt's sources, for Mesa $mesa_wanted" >&2
      printf 'Types: deb\nURIs: http://deb.debian.org/debian\nSuites: bookworm-backports\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' |
        $sudo tee /etc/apt/sources.list.d/bookworm-backports.sources >/dev/null
    fi
  fi
fi
if [ -n "$backports" ]; then  # installed from there below, not first from bookworm
  for i in "${!missing[@]}"; do [ "${missing[$i]}" != mesa-vulkan-drivers ] || unset 'missing[i]'; done
fi
if ((${#missing[@]})) || [ -n "$backports" ]; then
  $sudo apt-get update -qq
  if ((${#missing[@]})); then
    echo "setup: installing ${missing[*]}" >&2
    apt_install "${missing[@]}"
  fi
  if [ -n "$backports" ]; then
    echo "setup: installing mesa-vulkan-drivers from $backports" >&2
    apt_install -t "$backports" mesa-vulkan-drivers
  fi
fi

case "$mode" in
  sanitize)
    cmake --preset asan >/dev/null
    cmake --build --preset asan --parallel
    ctest --preset asan --parallel "$(nproc)" "${@:2}"
    exit
    ;;
  fuzz)
    cmake --preset fuzz >/dev/null
    cmake --build --preset fuzz --parallel
    exec tests/fuzz/run.sh "${2:-60}"
    ;;
esac

# A unity build (source files compiled in batches) halves a clean build on two cores; for
# incremental work on a few files, configure a build directory without it (DEVELOPERS.md).
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=ON >/dev/null
cmake --build build --parallel

case "$mode" in
  render)
    ./build/lancer render scenes/seed.toml -o seed.png
    echo "wrote $(pwd)/seed.png" >&2
    ;;
  test)
    ctest --test-dir build --output-on-failure --parallel "$(nproc)"
    ;;
  mesa22)
    exec tests/mesa22.sh "${@:2}"
    ;;
esac
