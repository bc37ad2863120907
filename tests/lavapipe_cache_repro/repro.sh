#!/usr/bin/env bash
# Mesa 25 llvmpipe/lavapipe (25.0.7): an image load compiled at one LP_NATIVE_VECTOR_WIDTH is taken
# from the on-disk shader cache at another. Runs image_load.comp at 256 bits (8 lanes), then at
# 512 bits (16 lanes) with the same fresh cache, then at 512 with the cache off; prints which
# invocations read a wrong value. Needs cc, glslangValidator and libvulkan (VK_ICD_FILENAMES
# picks the driver). Exit 0: all right; 1: wrong values (the bug); 77: no AVX-512, skipped.
#   bash tests/lavapipe_cache_repro/repro.sh
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
if ! grep -qw avx512f /proc/cpuinfo; then
    echo "skipped: 16-lane subgroups (LP_NATIVE_VECTOR_WIDTH=512) need AVX-512 (no avx512f)"
    exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cc -O1 -o "$work/runner" "$here/runner.c" -lvulkan
glslangValidator -V --target-env vulkan1.2 -o "$work/image_load.spv" "$here/image_load.comp" \
    >/dev/null
status=0
run() { # run LABEL WIDTH [ENV...]: invocation i must read i
    local label=$1 width=$2
    shift 2
    local out
    out=$(env "$@" LP_NATIVE_VECTOR_WIDTH="$width" MESA_SHADER_CACHE_DIR="$work/cache" \
        "$work/runner" "$work/image_load.spv" 2048 1)
    echo "$label: $(head -n 1 <<<"$out")"
    awk 'NR > 1 && $1 >= 1024 && $1 < 1536 && $2 != $1 - 1023 { bad = bad " " $1 - 1024 }
         NR > 1 && $1 >= 1536 { size = $2 - 1 }
         END { if (bad == "") print "  gl_SubgroupSize " size ", all 64 invocations read their texel"
               else { print "  gl_SubgroupSize " size ", wrong texel in invocations" bad; exit 1 } }' \
        <<<"$out" || status=1
}
run "8 lanes, empty cache" 256
run "16 lanes, the cache the 8-lane run filled" 512
run "16 lanes, cache off" 512 MESA_SHADER_CACHE_DISABLE=true
exit $status
