#!/usr/bin/env bash
# Time on the command line: --time and --frame pose scenes/animated_arm.gltf (different
# frames, different images; --frame N --fps F is --time N/F bit for bit); --frames writes every
# frame of a sequence, each bit for bit the separate render of that frame (with the tree rebuilt
# or refit between frames); bad ranges,
# patterns, animations and flag combinations are refused in one line with exit code 2.
# Usage: test_animation_cli.sh PATH/TO/wavefront PATH/TO/wf_compare_images SOURCE_DIR
set -u
wavefront=$1
compare=$2
scene=$3/scenes/animated_arm.gltf
source "$(dirname "$0")/harness.sh"
render() { "$wavefront" render "$scene" --spp 2 --width 32 --max-depth 3 --quiet "$@"; }
same() { "$compare" "$1" "$2" --spp 2 --tolerance 0 >/dev/null; }
differ() { ! same "$@"; }

check "--time" 0 render -o "$work/t0.5.exr" --time 0.5
check "--frame --fps" 0 render -o "$work/f12.exr" --frame 12 --fps 24
expect "--frame 12 at 24 fps is --time 0.5" same "$work/t0.5.exr" "$work/f12.exr"
check "--time 1.5" 0 render -o "$work/t1.5.exr" --time 1.5
expect "another time, another image" differ "$work/t0.5.exr" "$work/t1.5.exr"
check "--animation by name" 0 render -o "$work/play.exr" --time 0.5 --animation play
expect "--animation play is every animation here" same "$work/t0.5.exr" "$work/play.exr"

mkdir -p "$work/seq"
check "--frames" 0 render --frames 0..36:12 -o "$work/seq/frame_%04d.exr"
for f in 0 12 24 36; do
    check "--frame $f alone" 0 render --frame "$f" -o "$work/one_$f.exr"
    expect "--frames: frame $f equals its own render" \
        same "$work/seq/frame_$(printf %04d "$f").exr" "$work/one_$f.exr"
done
expect "--frames: only the frames asked for" test "$(ls "$work/seq" | grep -c 'exr$')" -eq 4
# One renderer for the sequence with a new tree every frame, or the first frame's tree refit:
# both bit for bit the separate renders here (the arm's light is a sphere, so the triangles'
# order, which a refit keeps from the first frame, changes no emitter table; closest hits do
# not depend on the tree). tests/gpu/test_frame_reuse.cpp holds refits with moving emissive
# triangles to 5 standard errors per region.
for mode in rebuild refit; do
    mkdir -p "$work/$mode"
    check "--frame-bvh $mode" 0 render --frames 0..36:12 --frame-bvh "$mode" \
        -o "$work/$mode/frame_%04d.exr"
    for f in 0 12 24 36; do
        expect "--frame-bvh $mode: frame $f equals its own render" \
            same "$work/$mode/frame_$(printf %04d "$f").exr" "$work/one_$f.exr"
    done
done
# --traversal rt where the device has ray-tracing pipelines: the sequence traces with them too
# (each frame the separate rt render of that frame).
if render --frame 0 --traversal rt -o "$work/probe.exr" 2>/dev/null; then
    mkdir -p "$work/rt"
    check "--frames --traversal rt" 0 render --frames 0..24:24 --traversal rt \
        -o "$work/rt/frame_%04d.exr"
    for f in 0 24; do
        check "--traversal rt --frame $f alone" 0 render --frame "$f" --traversal rt \
            -o "$work/rt/one_$f.exr"
        expect "--frames --traversal rt: frame $f equals its own render" \
            same "$work/rt/frame_$(printf %04d "$f").exr" "$work/rt/one_$f.exr"
    done
fi
# Motion blur around every frame: such frames are rebuilt (their keys come with the tree), and
# the kept renderer gives each the separate render's image.
mkdir -p "$work/shutter"
check "--frames --shutter" 0 render --frames 0..24:24 --shutter -0.5:0.5 \
    -o "$work/shutter/frame_%04d.exr"
for f in 0 24; do
    check "--shutter --frame $f alone" 0 render --frame "$f" --shutter -0.5:0.5 \
        -o "$work/shutter/one_$f.exr"
    expect "--frames --shutter: frame $f equals its own render" \
        same "$work/shutter/frame_$(printf %04d "$f").exr" "$work/shutter/one_$f.exr"
done
check "--frame-bvh refit says it refit" 0 "$wavefront" render "$scene" --spp 1 --width 16 \
    --max-depth 2 --frames 0..2 --frame-bvh refit -o "$work/refit/r_%d.exr"
expect "--frame-bvh refit: frames after the first refit" \
    test "$(grep -c '^wavefront: frame [12] .*(refit, cost' "$work/stderr")" -eq 2
expect "--frames: the renderer and its pipelines kept" grep -q "pipelines kept" "$work/stderr"
check "--frames prints per-frame times" 0 "$wavefront" render "$scene" --spp 1 --width 16 \
    --max-depth 2 --frames 3..4 -o "$work/seq/t_%d.exr"
expect "--frames: a line per frame" test "$(grep -c '^wavefront: frame [34] ' "$work/stderr")" -eq 2

refused() { # NAME ARGS...: exit 2, one line
    local name=$1
    shift
    check "$name" 2 "$@"
    expect "$name: one line" one_line_error
}
mkdir -p "$work/seq"
refused "--frames backwards" render --frames 5..2 -o "$work/seq/a_%d.exr"
refused "--frames step 0" render --frames 0..4:0 -o "$work/seq/a_%d.exr"
refused "--frames without a pattern" render --frames 0..2 -o "$work/seq/a.exr"
refused "--frames with two patterns" render --frames 0..2 -o "$work/seq/a_%d_%d.exr"
refused "--frames with --time" render --frames 0..2 --time 1 -o "$work/seq/a_%d.exr"
refused "--frame-bvh without --frames" render --frame-bvh refit -o "$work/x.exr"
refused "--frame-bvh unknown" render --frames 0..2 --frame-bvh sometimes -o "$work/seq/a_%d.exr"
refused "--time and --frame" render --time 1 --frame 2 -o "$work/x.exr"
refused "--fps alone" render --fps 30 -o "$work/x.exr"
refused "--animation unknown" render --animation walk -o "$work/x.exr"
expect "--animation unknown: lists the animations" grep -q "0 'play'" "$work/stderr"
expect "no output after refusals" test ! -e "$work/x.exr"
finish
