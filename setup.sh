#!/usr/bin/env bash
# lancer's one entry point for a fresh Debian 12 machine (run as root, or with sudo available):
#
#   ./setup.sh render   install the packages, build, render scenes/seed.toml to seed.png
#   ./setup.sh test     install the packages, build, run the whole test suite
#   ./setup.sh build    install the packages and build only
#   ./setup.sh sanitize the asan preset (ASan + UBSan) in build-asan/, and the whole suite under it
#   ./setup.sh fuzz [S] also clang: the fuzz targets in build-fuzz/, each run for S seconds (default 60)
#
# Packages are installed only when one is missing, so re-running is quick.
set -euo pipefail
cd "$(dirname "$0")"

mode="${1:-build}"
case "$mode" in render|test|build|sanitize|fuzz) ;; *) echo "usage: $0 render|test|build|sanitize|fuzz [seconds]" >&2; exit 2 ;; esac

# Every build and test dependency, all from Debian 12 (see DEVELOPERS.md for what each is for).
packages=(
  cmake ninja-build g++ pkg-config
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools
  glslang-dev glslang-tools spirv-tools
  libglm-dev libstb-dev libdeflate-dev liblapacke-dev libopenblas-dev libopenexr-dev
  libtomlplusplus-dev libcli11-dev libfmt-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  ffmpeg
  libsdl2-dev xvfb xdotool x11-apps
  parallel
)
# The fuzzers need clang, its runtimes (ASan, UBSan, libFuzzer) and llvm-symbolizer for readable
# stack traces; the other builds use g++ (whose sanitizer runtimes come with it).
if [ "$mode" = fuzz ]; then packages+=(clang libclang-rt-14-dev llvm); fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

case "$mode" in
  sanitize)
    cmake --preset asan >/dev/null
    cmake --build --preset asan --parallel
    ctest --preset asan --parallel "$(nproc)"
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
esac
