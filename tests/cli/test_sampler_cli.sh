#!/usr/bin/env bash
# The command line of the samplers and of `wavefront converge`: flags in --help, every sampler
# renders, bad values give exit 2 with one line, converge writes its files and ranking.
# Usage: test_sampler_cli.sh PATH/TO/wavefront PATH/TO/scenes
set -u
wavefront=$1
scenes=$2
source "$(dirname "$0")/harness.sh"
cornell="$scenes/cornell_box.gltf"

check "render help" 0 "$wavefront" render --help
for flag in --sampler --no-randomize --spp-offset --spp-total; do
    expect "render help lists $flag" grep -q -- "$flag" "$work/stdout"
done
check "top help" 0 "$wavefront" --help
expect "top help lists converge" grep -q "converge" "$work/stdout"
check "converge help" 0 "$wavefront" converge --help
for flag in --output --reference --reference-spp --time --methods --seeds --max-spp --target \
    --width --height --max-depth --crop --no-plot; do
    expect "converge help lists $flag" grep -q -- "$flag" "$work/stdout"
done

for sampler in independent stratified multijitter halton hammersley sobol bluenoise; do
    check "render --sampler $sampler" 0 "$wavefront" render "$cornell" -o "$work/$sampler.exr" \
        --spp 2 --width 8 --max-depth 3 --sampler "$sampler" -q
    expect "$sampler: sampler in the EXR header" grep -qa "$sampler" "$work/$sampler.exr"
done
check "partial render" 0 "$wavefront" render "$cornell" -o "$work/part.exr" --spp 2 --width 8 \
    --spp-offset 2 --spp-total 4 --sampler hammersley -q
expect "partial render: offset in the EXR header" grep -qa "sppOffset" "$work/part.exr"
check "no-randomize" 0 "$wavefront" render "$cornell" -o "$work/n.exr" --spp 1 --width 8 \
    --no-randomize --sampler halton -q

check "unknown sampler" 2 "$wavefront" render "$cornell" -o "$work/x.exr" --sampler pmj
expect "unknown sampler: one line" one_line_error
expect "unknown sampler: lists the samplers" grep -q "bluenoise" "$work/stderr"
check "set smaller than the part" 2 "$wavefront" render "$cornell" -o "$work/x.exr" --spp 4 \
    --spp-offset 1 --spp-total 4
expect "set smaller: one line" one_line_error
check "independent cannot un-randomize" 2 "$wavefront" render "$cornell" -o "$work/x.exr" \
    --sampler independent --no-randomize
expect "independent no-randomize: one line" one_line_error

conv="$work/conv"
check "converge" 0 "$wavefront" converge "$cornell" -o "$conv" --width 8 --time 0.01 \
    --max-spp 4 --reference-spp 8 --methods independent,sobol+nee --max-depth 3 -q
for file in convergence.csv convergence.json reference.exr crops/reference.png \
    crops/sobol+nee.png crops/independent+mis.png; do
    expect "converge wrote $file" test -s "$conv/$file"
done
expect "converge prints a ranking" grep -q "ranking by GPU time" "$work/stdout"
expect "converge says it rendered the reference" grep -q "rendering one with Wavefront" \
    "$work/stderr"
expect "csv: 5 seeds" bash -c \
    "cut -d, -f4 '$conv/convergence.csv' | sort -u | grep -c . | grep -q 6"
if /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
    for chart in error_vs_time.png error_vs_spp.png equal_time.png; do
        expect "converge drew $chart" test -s "$conv/$chart"
    done
fi
check "converge with a given reference" 0 "$wavefront" converge "$cornell" -o "$work/conv2" \
    --reference "$conv/reference.exr" --time 0.01 --max-spp 2 --methods halton \
    --max-depth 3 --no-plot -q
expect "given reference: size adopted" json_has "$work/conv2/convergence.json" \
    "d['width'] == 8 and d['reference']['method'] == 'given'"
expect "json: medians, quartiles, slopes" json_has "$conv/convergence.json" \
    "all(len(m['relMse']) == len(m['relMseQ1']) == len(m['spp']) and 'slopeSpp' in m
         for m in d['methods']) and d['ranking'] and len(d['seeds']) == 5"

check "converge guided" 0 "$wavefront" converge "$cornell" -o "$work/conv3" \
    --reference "$conv/reference.exr" --time 0.01 --max-spp 4 --methods sobol,sobol+guided \
    --max-depth 3 --no-plot -q
expect "converge guided: a method of its own" json_has "$work/conv3/convergence.json" \
    "[m['name'] for m in d['methods']] == ['sobol+mis', 'sobol+mis+guided']"
check "converge: guided with adaptive" 0 "$wavefront" converge "$cornell" -o "$work/c4" \
    --reference "$conv/reference.exr" --time 0.01 --max-spp 8 --methods sobol+guided+adaptive \
    --max-depth 3 --no-plot -q
expect "guided with adaptive: a method of its own" json_has "$work/c4/convergence.json" \
    "[m['name'] for m in d['methods']] == ['sobol+mis+adaptive+guided']"
check "converge: --guiding instead of the word" 2 "$wavefront" converge "$cornell" \
    -o "$work/c3" --guiding on
expect "converge --guiding: one line" one_line_error

check "converge: too few seeds" 2 "$wavefront" converge "$cornell" -o "$work/c3" --seeds 2
expect "too few seeds: one line" one_line_error
check "converge: unknown method word" 2 "$wavefront" converge "$cornell" -o "$work/c3" \
    --methods sobol+fast
expect "unknown method word: one line" one_line_error
check "converge: no output" 2 "$wavefront" converge "$cornell"
check "converge: reference of another size" 2 "$wavefront" converge "$cornell" -o "$work/c3" \
    --reference "$conv/reference.exr" --width 16
expect "reference size: one line" one_line_error
check "converge: bad crop" 2 "$wavefront" converge "$cornell" -o "$work/c3" --width 8 \
    --crop 4,4,8,8
expect "bad crop: one line" one_line_error

# --integrator light: an image, its counts in the EXR and JSON, one-line refusals.
check "render --integrator light" 0 "$wavefront" render "$cornell" -o "$work/light.exr" \
    --spp 4 --width 8 --max-depth 4 --integrator light --json "$work/light.json" -q
expect "light: integrator in the EXR header" grep -qa "lightPaths" "$work/light.exr"
expect "light: both counts in the JSON" json_has "$work/light.json" \
    "d['integrator'] == 'light' and d['lightPaths'] == d['cameraSamples'] == 4 * 8 * 8"
check "bdpt part 1" 0 "$wavefront" render "$cornell" -o "$work/b0.exr" --spp 2 --width 8 \
    --spp-total 4 --integrator bdpt -q
check "bdpt part 2" 0 "$wavefront" render "$cornell" -o "$work/b1.exr" --spp 2 --width 8 \
    --spp-offset 2 --spp-total 4 --integrator bdpt -q
check "bdpt parts merge" 0 "$wavefront" merge "$work/b0.exr" "$work/b1.exr" -o "$work/b.exr" -q
check "a light part does not merge with a bdpt part" 2 "$wavefront" merge "$work/b0.exr" \
    "$work/light.exr" -o "$work/x.exr" -q
expect "light and bdpt parts: one line" one_line_error
check "light with --target-error" 2 "$wavefront" render "$cornell" -o "$work/x.exr" \
    --integrator light --target-error 0.01 --width 8
expect "light with --target-error: one line" one_line_error
check "unknown integrator" 2 "$wavefront" render "$cornell" -o "$work/x.exr" --integrator sppm
expect "unknown integrator: one line" one_line_error
# vcm: consistent, not unbiased, and labelled so in the EXR and JSON.
check "render --integrator vcm" 0 "$wavefront" render "$cornell" -o "$work/vcm.exr" \
    --spp 2 --width 8 --max-depth 4 --integrator vcm --vcm-radius 0.05 --json "$work/vcm.json" -q
expect "vcm: labelled consistent in the EXR header" grep -qa "consistent, not unbiased" \
    "$work/vcm.exr"
expect "vcm: labelled in the JSON" json_has "$work/vcm.json" \
    "d['integrator'] == 'vcm' and d['unbiased'] is False and d['vcmRadius'] == 0.05 and 'variance only' in d['errorEstimateMeasures']"
check "--vcm-radius with bdpt" 2 "$wavefront" render "$cornell" -o "$work/x.exr" \
    --integrator bdpt --vcm-radius 0.05 --width 8
expect "--vcm-radius with bdpt: one line" one_line_error
check "converge light" 0 "$wavefront" converge "$cornell" -o "$work/c5" \
    --reference "$conv/reference.exr" --time 0.01 --max-spp 4 \
    --methods sobol,sobol+light,sobol+vcm --max-depth 3 --no-plot -q
expect "converge light: a method of its own" json_has "$work/c5/convergence.json" \
    "[(m['name'], m['integrator']) for m in d['methods']] == [('sobol+mis', 'path'), ('sobol+light', 'light'), ('sobol+vcm', 'vcm')]"
check "converge: light and nee" 2 "$wavefront" converge "$cornell" -o "$work/c3" \
    --methods sobol+light+nee
expect "light and nee: one line" one_line_error

finish
