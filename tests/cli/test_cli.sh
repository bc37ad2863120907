#!/usr/bin/env bash
# The command-line contract of `wavefront render`: outputs, exit codes, one-line errors.
# Usage: test_cli.sh PATH/TO/wavefront PATH/TO/scenes
set -u
wavefront=$1
scenes=$2
source "$(dirname "$0")/harness.sh"

check "top help" 0 "$wavefront" --help
expect "top help lists render" grep -q "render" "$work/stdout"
check "render help" 0 "$wavefront" render --help
for flag in --output --spp --width --height --max-depth --rr-depth --seed --json --quiet \
    --device --light-sampling --light-selection --triangle-sampling --sphere-sampling \
    --min-throughput --clamp --aperture --focus-distance --texture-filter --traversal; do
    expect "render help lists $flag" grep -q -- "$flag" "$work/stdout"
done

out="$work/cornell.exr"
check "render" 0 "$wavefront" render "$scenes/cornell_box.gltf" -o "$out" --spp 4 --width 64 \
    --max-depth 4 --seed 9 --json "$work/stats.json"
expect "exr written" test -s "$out"
expect "png written" test -s "$work/cornell.png"
expect "png signature" bash -c "head -c 8 '$work/cornell.png' | od -An -tx1 | grep -q '89 50 4e 47 0d 0a 1a 0a'"
expect "json has paths/s" grep -q '"pathsPerSecond"' "$work/stats.json"
expect "json has shadow rays/s" grep -q '"shadow"' "$work/stats.json"
expect "json spp" grep -q '"spp": 4' "$work/stats.json"
expect "json scene and bvh build" json_has "$work/stats.json" \
    "d['triangles'] > 0 and d['bvh']['nodes'] > 0 and d['bvh']['buildSeconds'] >= 0 and \
     d['bvh']['threads'] >= 1 and d['peakHostMemoryBytes'] > 0 and d['loadSeconds'] > 0"
expect "progress on stderr" grep -q "spp" "$work/stderr"
# The PNG preview's tone curve: Khronos PBR Neutral unless told; the EXR stays linear radiance.
for curve in linear aces neutral; do
    check "render --tonemap $curve" 0 "$wavefront" render "$scenes/cornell_box.gltf" \
        -o "$work/tone_$curve.exr" --spp 4 --width 64 --max-depth 4 --seed 9 --tonemap $curve -q
done
expect "neutral is the default preview" cmp "$work/cornell.png" "$work/tone_neutral.png"
expect "tone curves differ" bash -c "! cmp -s '$work/tone_linear.png' '$work/tone_neutral.png' \
    && ! cmp -s '$work/tone_aces.png' '$work/tone_neutral.png'"
check "bad tonemap" 2 "$wavefront" render "$scenes/cornell_box.gltf" -o "$work/x.exr" \
    --tonemap filmic
expect "bad tonemap: one line" one_line_error
expect "no temp files left" bash -c "! ls '$work' | grep -q tmp"

check "thin lens" 0 "$wavefront" render "$scenes/cornell_box.gltf" -o "$work/lens.exr" --spp 2 \
    --width 24 --max-depth 2 --aperture 0.3 --focus-distance 8 --verbose --quiet
expect "thin lens: its variant" grep -q "WF_THIN_LENS=1" "$work/stderr"
check "negative aperture" 2 "$wavefront" render "$scenes/cornell_box.gltf" -o "$work/x.exr" \
    --aperture -1
expect "negative aperture: one line" one_line_error

# --traversal: bvh always; rt where the device has ray-tracing pipelines (Mesa 25's lavapipe),
# else a one-line refusal, exit 2; auto picks bvh on lavapipe (a CPU device, where it measured
# faster) and says so in the JSON.
check "bad traversal" 2 "$wavefront" render "$scenes/cornell_box.gltf" -o "$work/x.exr" \
    --traversal embree
expect "bad traversal: one line" one_line_error
check "traversal bvh" 0 "$wavefront" render "$scenes/cornell_box.gltf" -o "$work/t.exr" --spp 1 \
    --width 16 --max-depth 3 --traversal bvh --quiet --json "$work/bvh.json"
expect "traversal bvh: json" json_has "$work/bvh.json" "d['traversal']['mode'] == 'bvh'"
"$wavefront" render "$scenes/cornell_box.gltf" -o "$work/t.exr" --spp 1 --width 16 \
    --max-depth 3 --traversal rt --verbose --json "$work/rt.json" >"$work/stdout" 2>"$work/stderr"
rt_code=$?
if [ "$rt_code" -eq 0 ]; then
    expect "traversal rt: json" json_has "$work/rt.json" "d['traversal']['mode'] == 'rt' and \
        d['traversal']['accelerationBytes'] > 0 and d['traversal']['accelerationBuildSeconds'] >= 0"
    expect "traversal rt: verbose says so" grep -q "traversal: rt" "$work/stderr"
else
    expect "traversal rt refused with exit 2" test "$rt_code" -eq 2
    expect "traversal rt refused: one line" one_line_error
    expect "traversal rt refused: says why" grep -q "ray-tracing pipelines" "$work/stderr"
fi
check "traversal auto" 0 "$wavefront" render "$scenes/cornell_box.gltf" -o "$work/t.exr" \
    --spp 1 --width 16 --max-depth 3 --quiet --json "$work/auto.json"
if grep -q llvmpipe "$work/auto.json"; then
    expect "traversal auto: bvh on lavapipe" json_has "$work/auto.json" \
        "d['traversal']['mode'] == 'bvh'"
fi

textured="$(dirname "${BASH_SOURCE[0]}")/../gltf_corpus/valid/normal_map_cylinder_mirrored.gltf"
check "texture filter" 0 "$wavefront" render "$textured" -o "$work/tf.exr" --spp 1 --width 16 \
    --max-depth 2 --verbose --quiet
expect "texture filter: ray cones in the textured variant" grep -q "WF_RAY_CONES=1" "$work/stderr"
check "texture filter none" 0 "$wavefront" render "$textured" -o "$work/tf.exr" --spp 1 \
    --width 16 --max-depth 2 --texture-filter none --verbose --quiet
expect "texture filter none: no ray cones" grep -q "WF_RAY_CONES=0" "$work/stderr"
check "bad texture filter" 2 "$wavefront" render "$textured" -o "$work/x.exr" --texture-filter box
expect "bad texture filter: one line" one_line_error

check "quiet render" 0 "$wavefront" render "$scenes/cornell_box.gltf" -o "$work/q.exr" --spp 1 \
    --width 16 --quiet
expect "quiet prints nothing" test ! -s "$work/stderr"

check "no arguments" 2 "$wavefront"
check "unknown command" 2 "$wavefront" frobnicate
expect "unknown command: one line" one_line_error
check "unknown flag" 2 "$wavefront" render "$scenes/cornell_box.gltf" -o "$work/x.exr" --bogus
expect "unknown flag: one line" one_line_error
check "missing output" 2 "$wavefront" render "$scenes/cornell_box.gltf"
check "bad spp" 2 "$wavefront" render "$scenes/cornell_box.gltf" -o "$work/x.exr" --spp -3
expect "bad spp: one line" one_line_error
check "bad light sampling" 2 "$wavefront" render "$scenes/cornell_box.gltf" -o "$work/x.exr" \
    --light-sampling magic
expect "bad light sampling: one line" one_line_error
check "bad light selection" 2 "$wavefront" render "$scenes/cornell_box.gltf" -o "$work/x.exr" \
    --light-selection nearest
expect "bad light selection: one line" one_line_error
for selection in uniform power tree; do
    check "light selection $selection" 0 "$wavefront" render "$scenes/many_lamps.gltf" \
        -o "$work/$selection.exr" --spp 1 --width 24 --quiet --light-selection $selection
done
check "verbose names the light tree" 0 "$wavefront" render "$scenes/many_lamps.gltf" \
    -o "$work/lamps.exr" --spp 1 --width 16 --verbose
expect "verbose: light tree of 4096 lights" grep -q "light selection: tree (light tree of 4096 lights" \
    "$work/stderr"
check "negative clamp" 2 "$wavefront" render "$scenes/cornell_box.gltf" -o "$work/x.exr" --clamp -1
for mode in bsdf nee mis; do
    check "light sampling $mode" 0 "$wavefront" render "$scenes/cornell_box.gltf" \
        -o "$work/$mode.exr" --spp 2 --width 24 --quiet --light-sampling $mode \
        --triangle-sampling area --sphere-sampling area --min-throughput 0.01 --clamp 50
done
check "spp zero" 2 "$wavefront" render "$scenes/cornell_box.gltf" -o "$work/x.exr" --spp 0
check "missing scene" 2 "$wavefront" render "$work/none.gltf" -o "$work/x.exr"
expect "missing scene: one line" one_line_error
printf '{ not json' >"$work/bad.gltf"
check "malformed scene" 2 "$wavefront" render "$work/bad.gltf" -o "$work/x.exr"
expect "malformed scene: one line" one_line_error
check "output folder missing" 2 "$wavefront" render "$scenes/cornell_box.gltf" \
    -o "$work/no/such/dir/x.exr" --spp 1 --width 8
expect "nothing written on failure" test ! -e "$work/x.exr"
# KHR_materials_variants: --variant picks one at load and --verbose lists them; an unknown
# one, by name or index, or one asked of a file without variants: exit 2 in one line.
python3 "$(dirname "$0")/variants_gltf.py" "$work/variants.gltf"
check "variant by name" 0 "$wavefront" render "$work/variants.gltf" -o "$work/variant.exr" \
    --spp 1 --width 8 --max-depth 1 --variant blue --verbose --quiet
expect "verbose lists the variants" grep -q "variants: 0 'red', 1 'blue' (chosen)" "$work/stderr"
expect "variants: no ignored-extension warning" bash -c \
    "! grep -q 'ignoring glTF extension KHR_materials_variants' '$work/stderr'"
check "unknown variant" 2 "$wavefront" render "$work/variants.gltf" -o "$work/x.exr" \
    --variant green
expect "unknown variant: one line" one_line_error
check "variant index out of range" 2 "$wavefront" render "$work/variants.gltf" \
    -o "$work/x.exr" --variant 2
expect "variant index out of range: one line" one_line_error
check "variant of a file without variants" 2 "$wavefront" render "$scenes/cornell_box.gltf" \
    -o "$work/x.exr" --variant red
expect "variant without variants: one line" one_line_error
check "bad device" 2 "$wavefront" render "$scenes/cornell_box.gltf" -o "$work/x.exr" --device 7

finish
