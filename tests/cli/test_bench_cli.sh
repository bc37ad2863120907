#!/usr/bin/env bash
# The command-line contract of `wavefront bench`: help, the table, the JSON report, the
# megakernel comparison, identical ray counts for identical inputs, and usage errors.
# Usage: test_bench_cli.sh PATH/TO/wavefront PATH/TO/scenes
set -u
wavefront=$1
scenes=$2
source "$(dirname "$0")/harness.sh"

check "top help" 0 "$wavefront" --help
expect "top help lists bench" grep -q "bench SCENE" "$work/stdout"
check "bench help" 0 "$wavefront" bench --help
for flag in --width --height --frames --warmup --spp --max-depth --seed --megakernel \
    --compare-megakernel --budget-ms --wave-paths --json --device --sampler \
    --triangle-sampling --sphere-sampling --min-throughput --clamp --no-randomize --camera --env \
    --shade-split --traversal; do
    expect "bench help lists $flag" grep -q -- "$flag" "$work/stdout"
done

small=(--width 32 --height 32 --frames 3 --warmup 1 --max-depth 5 -q)
check "bench" 0 "$wavefront" bench "$scenes/cornell_box.gltf" "${small[@]}" --json "$work/a.json"
for word in raygen intersect shade queue shadow accumulate "frame (wall)" "paths/s" \
    "longest" "depth" "device memory" "SAH cost" "shader variant"; do
    expect "table shows $word" grep -q -- "$word" "$work/stdout"
done
pass_names="('raygen', 'intersect', 'shade', 'queue', 'shadow', 'accumulate')"
run="d['runs']['wavefront']"
expect "json has every pass" json_has "$work/a.json" \
    "all(k in $run['passMilliseconds'] for k in $pass_names)"
expect "json has min/median/max" json_has "$work/a.json" \
    "$run['passMilliseconds']['intersect']['median'] >= 0"
expect "json has occupancy" json_has "$work/a.json" "$run['occupancy'][0]['rays'] == 32*32*3"
expect "json has memory and BVH" json_has "$work/a.json" \
    "$run['memoryTotalBytes'] > 0 and d['bvh']['sahCost'] > 0"

expect "json: bvh traversal by default on lavapipe" json_has "$work/a.json" \
    "d['traversal']['mode'] == 'bvh' or 'llvmpipe' not in d['device']"
# --traversal rt where the device has ray-tracing pipelines: the table and the JSON say so,
# with the structures' size and build time; the megakernel beside it walks the BVH.
if "$wavefront" bench "$scenes/cornell_box.gltf" "${small[@]}" --traversal rt \
    --compare-megakernel --json "$work/rt.json" >"$work/stdout" 2>"$work/stderr"; then
    expect "rt: table says so" grep -q "traversal: rt" "$work/stdout"
    expect "rt: the megakernel walks the BVH" grep -q "the megakernel walks the BVH" \
        "$work/stdout"
    expect "rt: json" json_has "$work/rt.json" "d['traversal']['mode'] == 'rt' and \
        d['traversal']['megakernel'] == 'bvh' and d['traversal']['accelerationBytes'] > 0"
    expect "rt: same rays as bvh" json_has "$work/rt.json" \
        "d['runs']['wavefront']['occupancy'][0]['rays'] == 32*32*3"
else
    expect "rt refused: one line" one_line_error
fi

check "bench split by kind" 0 "$wavefront" bench "$scenes/glass_caustic.gltf" "${small[@]}" \
    --json "$work/k.json"
expect "a shade pass per kind" json_has "$work/k.json" \
    "all(k in $run['passMilliseconds'] for k in ('shade diffuse', 'shade specular'))"
check "bench split off" 0 "$wavefront" bench "$scenes/glass_caustic.gltf" "${small[@]}" \
    --shade-split off --json "$work/o.json"
expect "one shade pass, the same rays" python3 -c "
import json, sys
k, o = (json.load(open(f))['runs']['wavefront'] for f in sys.argv[1:])
sys.exit(0 if 'shade' in o['passMilliseconds'] and k['rays'] == o['rays'] else 1)" \
    "$work/k.json" "$work/o.json"

check "bench again" 0 "$wavefront" bench "$scenes/cornell_box.gltf" "${small[@]}" \
    --json "$work/b.json" --budget-ms 1
expect "same inputs, same ray counts (any wave size)" python3 -c "
import json, sys
a, b = (json.load(open(f))['runs']['wavefront'] for f in sys.argv[1:])
sys.exit(0 if a['rays'] == b['rays'] and a['occupancy'] == b['occupancy'] else 1)" \
    "$work/a.json" "$work/b.json"

check "compare megakernel" 0 "$wavefront" bench "$scenes/cornell_box.gltf" "${small[@]}" \
    --compare-megakernel --json "$work/m.json"
expect "both tables and the ratio" grep -q "wavefront / megakernel" "$work/stdout"
expect "megakernel table" grep -q "^megakernel:" "$work/stdout"
expect "json ratio" json_has "$work/m.json" "d['wavefrontOverMegakernel'] > 0"
expect "equal workloads" json_has "$work/m.json" \
    "$run['rays'] == d['runs']['megakernel']['rays']"
check "megakernel" 0 "$wavefront" bench "$scenes/cornell_box.gltf" "${small[@]}" --megakernel
expect "megakernel table only" bash -c "! grep -q '^wavefront:' '$work/stdout'"

# The transport, sampler and scene flags are render's (src/app/render_options.h).
check "bench sampler flags" 0 "$wavefront" bench "$scenes/cornell_box.gltf" "${small[@]}" \
    --sampler independent --triangle-sampling area --sphere-sampling area --clamp 10
check "bad sampler" 2 "$wavefront" bench "$scenes/cornell_box.gltf" "${small[@]}" --sampler nope
expect "bad sampler: one line" one_line_error
expect "bad sampler: lists the samplers" grep -q "sobol" "$work/stderr"
check "no-randomize needs a randomized sampler" 2 "$wavefront" bench \
    "$scenes/cornell_box.gltf" "${small[@]}" --sampler independent --no-randomize
check "no scene" 2 "$wavefront" bench
check "bad frames" 2 "$wavefront" bench "$scenes/cornell_box.gltf" --frames 0
check "unknown flag" 2 "$wavefront" bench "$scenes/cornell_box.gltf" --bogus

finish
