#!/usr/bin/env bash
# --shutter on the command line: scenes/animated_arm.gltf's sliding block blurs (an image unlike
# the sharp frame, WF_MOTION in the variant, its skinned arm and morphed tent warned as drawn at
# the shutter's centre); a shutter within which nothing moves leaves the image bit for bit the
# still one; converge takes --frame beside its --time budget; malformed intervals, the viewer and --traversal rt are refused in one line, exit 2.
# Usage: test_motion_cli.sh PATH/TO/wavefront PATH/TO/wf_compare_images SOURCE_DIR
set -u
wavefront=$1
compare=$2
scene=$3/scenes/animated_arm.gltf
source "$(dirname "$0")/harness.sh"
render() { "$wavefront" render "$scene" --spp 4 --width 32 --max-depth 3 "$@"; }
same() { "$compare" "$1" "$2" --spp 4 --tolerance 0 >/dev/null; }
differ() { ! same "$@"; }

check "sharp" 0 render --quiet --time 0.5 -o "$work/sharp.exr"
check "--shutter" 0 render --verbose --time 0.5 --shutter -6:6 -o "$work/blur.exr"
expect "--shutter: WF_MOTION compiled in" grep -q "WF_MOTION=1" "$work/stderr"
expect "--shutter: the skinned arm is warned about" grep -q "deforms within the shutter" \
    "$work/stderr"
expect "--shutter: a blurred image" differ "$work/sharp.exr" "$work/blur.exr"
# The animation ends at 2 s: after it nothing moves.
check "still late" 0 render --quiet --time 5 -o "$work/late.exr"
check "--shutter, nothing moving" 0 render --verbose --time 5 --shutter -0.5:0.5 \
    -o "$work/late_blur.exr"
expect "nothing moving: no WF_MOTION" bash -c "! grep -q WF_MOTION '$work/stderr'"
expect "nothing moving: bit for bit the still image" same "$work/late.exr" "$work/late_blur.exr"
check "--shutter with --fps" 0 render --quiet --time 0.5 --shutter -3:3 --fps 12 \
    -o "$work/fps.exr"
expect "--shutter -3:3 at 12 fps is -6:6 at 24" same "$work/blur.exr" "$work/fps.exr"

# converge: --time is its budget, the scene's time --frame (which once clashed with it).
check "converge --frame --shutter --time" 0 "$wavefront" converge "$scene" -o "$work/conv" \
    --frame 12 --shutter -2:2 --time 0.05 --methods sobol --width 16 --reference-spp 16 \
    --max-spp 4 --no-plot --quiet
expect "converge: wrote its results" test -s "$work/conv/convergence.json"

refused() { # NAME ARGS...: exit 2, one line
    local name=$1
    shift
    check "$name" 2 "$@"
    expect "$name: one line" one_line_error
}
refused "--shutter backwards" render --shutter 0.5:-0.5 -o "$work/x.exr"
refused "--shutter without a colon" render --shutter 0.5 -o "$work/x.exr"
refused "--shutter not a number" render --shutter a:b -o "$work/x.exr"
refused "--shutter infinite" render --shutter -inf:1 -o "$work/x.exr"
refused "--shutter with rt" render --shutter -1:1 --traversal rt -o "$work/x.exr"
refused "--shutter in the viewer" "$wavefront" view "$scene" --shutter -1:1
expect "no output after refusals" test ! -e "$work/x.exr"
finish
