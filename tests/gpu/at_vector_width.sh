#!/usr/bin/env bash
# GPU gtests at one lavapipe vector width, so that no change is right at 8 lanes only:
#   at_vector_width.sh BITS CACHE_DIR GTEST_BINARY GTEST_FILTER
# 128 bits gives 4-lane subgroups, 512 bits 16 (skipped, exit 77, where the CPU lacks AVX-512).
# A short run at the default width fills the same Mesa shader cache first, as a user's cache
# would be: Mesa 25's llvmpipe once handed the 8-lane image loads from it to 16-lane shaders
# (issue 33, tests/lavapipe_cache_repro/).
set -euo pipefail
bits=$1 cache=$2 binary=$3 filter=$4
if [ "$bits" -gt 256 ] && ! grep -qw avx512f /proc/cpuinfo; then
    echo "skipped: LP_NATIVE_VECTOR_WIDTH=$bits needs AVX-512 (no avx512f in /proc/cpuinfo)"
    exit 77
fi
mkdir -p "$cache"
export MESA_SHADER_CACHE_DIR=$cache WAVEFRONT_VALIDATION=1
if ! primed=$(env -u LP_NATIVE_VECTOR_WIDTH "$binary" --gtest_filter='FurnaceDepth.*' 2>&1); then
    echo "$primed"
    echo "at_vector_width: the default-width run before the $bits-bit one failed"
    exit 1
fi
LP_NATIVE_VECTOR_WIDTH=$bits "$binary" --gtest_filter="$filter" --gtest_brief=1
