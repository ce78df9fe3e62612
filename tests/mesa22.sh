#!/usr/bin/env bash
# The GPU tests (label render, and the file size limits) on Debian 12's own lavapipe, Mesa 22.3,
# while the system has Mesa 25 from bookworm-backports: the driver package is downloaded once
# into build/mesa22/, unpacked there, and chosen with VK_DRIVER_FILES for these tests only. Mesa
# 22.3 limits loop iterations and allocates device memory differently (gpu/vulkan/driver_quirks.hpp):
# these runs keep both code paths honest. Run through ./setup.sh mesa22 [CTEST ARGS] (after a
# build): with ctest arguments, only the tests they select (CI: every shipped scene against the
# reference, the loop limit and the file size limits).
set -euo pipefail
cd "$(dirname "$0")/.."
dir=build/mesa22
release=bookworm  # Debian 12's own version, not the backport
if [ ! -f "$dir/lvp_icd.json" ]; then
  rm -rf "$dir" && mkdir -p "$dir/root"
  (cd "$dir" && apt-get download "mesa-vulkan-drivers/$release" 2>/dev/null)
  dpkg-deb -x "$dir"/mesa-vulkan-drivers_*.deb "$dir/root"
  library=$(find "$(pwd)/$dir/root" -name libvulkan_lvp.so | head -n 1)
  [ -n "$library" ] || { echo "mesa22: no libvulkan_lvp.so in the package" >&2; exit 1; }
  printf '{"file_format_version": "1.0.0", "ICD": {"library_path": "%s", "api_version": "1.1.230"}}\n' \
    "$library" >"$dir/lvp_icd.json"
fi
export VK_DRIVER_FILES="$(pwd)/$dir/lvp_icd.json" VK_ICD_FILENAMES="$(pwd)/$dir/lvp_icd.json"
devices=$(build/lancer render --list-devices)
echo "mesa22: $devices" >&2
case "$devices" in *"Mesa 22."*) ;; *) echo "mesa22: the device is not Mesa 22's lavapipe" >&2; exit 1 ;; esac
if (($#)); then
  exec ctest --test-dir build --output-on-failure --parallel "$(nproc)" "$@"
fi
ctest --test-dir build --output-on-failure --parallel "$(nproc)" -L render
ctest --test-dir build --output-on-failure --parallel "$(nproc)" -R '^Faults\.FileSizeLimit'
