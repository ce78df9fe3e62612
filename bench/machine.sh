#!/usr/bin/env bash
# Prints the machine a benchmark ran on, for the first lines of its output: the CPU model, its
# cores and the vector extensions lavapipe's code generator can use (AVX, AVX2, AVX-512, FMA),
# and the Vulkan device with its driver. lavapipe's speed depends on the CPU far more than
# C++'s does (docs/performance.md), so no figure means anything without these.
#   source bench/machine.sh; machine_description
machine_description() {
  local model cores flags vec=()
  model=$(lscpu | sed -nE 's/^Model name: *//p' | head -n 1)
  cores=$(nproc)
  # Virtual machines often report only "AMD EPYC": the family and model tell Zen 3 (25/1),
  # Zen 4 (25/17) and Zen 5 (26/2) apart, and Intel's generations alike.
  local family number
  family=$(lscpu | sed -nE 's/^CPU family: *//p' | head -n 1)
  number=$(lscpu | sed -nE 's/^Model: *//p' | head -n 1)
  [ -n "$family" ] && model="$model (family $family, model ${number:-?})"
  flags=" $(lscpu | sed -nE 's/^Flags: *//p') "
  for f in avx avx2 fma avx512f avx512vl avx512bw; do [[ $flags == *" $f "* ]] && vec+=("$f"); done
  echo "CPU: ${model:-unknown}, ${cores} cores, vector extensions: ${vec[*]:-none beyond SSE}"
  [ -n "${GALLIUM_OVERRIDE_CPU_CAPS:-}" ] && echo "GALLIUM_OVERRIDE_CPU_CAPS=$GALLIUM_OVERRIDE_CPU_CAPS (lavapipe's code generator told to use only these)"
  if [ -x build/lancer ]; then
    build/lancer render --list-devices 2>/dev/null | sed 's/^/Vulkan: /' | head -n 3
  fi
}
