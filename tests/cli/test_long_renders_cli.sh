#!/usr/bin/env bash
# Long renders end to end: `wavefront merge` (parts of one render merge into the image of one
# run; parts of another render, overlapping ranges and non-parts are refused in one line, exit
# 2; a gap is reported), `render --time-limit` (stops on a whole pass), --aov layers, and
# --target-error, checkpoints (SIGTERM writes one; --resume continues it to the image of an uninterrupted run,
# and refuses a checkpoint of another render).
# Usage: test_long_renders_cli.sh PATH/TO/wavefront PATH/TO/wf_compare_images PATH/TO/scenes
set -u
wavefront=$1
compare=$2
scenes=$3
source "$(dirname "$0")/harness.sh"
box="$scenes/cornell_box.gltf"
part() { # part NAME OFFSET SPP [flags]
    local name=$1 offset=$2 spp=$3
    shift 3
    check "render part $name" 0 "$wavefront" render "$box" -o "$work/$name.exr" --spp "$spp" \
        --spp-offset "$offset" --width 40 --max-depth 4 --quiet "$@"
}

check "merge help" 0 "$wavefront" merge --help
expect "merge help lists --output" grep -q -- "--output" "$work/stdout"
check "top help lists merge" 0 "$wavefront" --help
expect "top help: merge" grep -q "merge" "$work/stdout"

# Unequal parts, so that a plain mean of the images would not do.
part a 0 8
part b 8 16
part c 24 8
check "one run of 32 spp" 0 "$wavefront" render "$box" -o "$work/one.exr" --spp 32 --width 40 \
    --max-depth 4 --quiet
check "merge three parts" 0 "$wavefront" merge "$work/c.exr" "$work/a.exr" "$work/b.exr" \
    -o "$work/merged.exr"
expect "merged png written" test -s "$work/merged.png"
expect "merge names the range" grep -q "samples 0-31 (32 spp)" "$work/stderr"
check "merged = one run" 0 "$compare" "$work/merged.exr" "$work/one.exr" --spp 32 \
    --tolerance 1e-5

check "merge with a gap" 0 "$wavefront" merge "$work/a.exr" "$work/c.exr" -o "$work/gap.exr"
expect "gap reported" grep -q "samples 8-23 are in no part" "$work/stderr"

check "overlapping parts" 2 "$wavefront" merge "$work/a.exr" "$work/a.exr" -o "$work/x.exr"
expect "overlap: one line" one_line_error
part s 8 8 --seed 5
check "part of another seed" 2 "$wavefront" merge "$work/a.exr" "$work/s.exr" -o "$work/x.exr"
expect "another seed: one line" one_line_error
part d 8 8 --max-depth 3
check "part of other settings" 2 "$wavefront" merge "$work/a.exr" "$work/d.exr" -o "$work/x.exr"
expect "other settings: one line" one_line_error
check "part of another scene" 0 "$wavefront" render "$scenes/tiny_light.gltf" -o "$work/t.exr" \
    --spp 8 --spp-offset 8 --width 40 --max-depth 4 --quiet
check "parts of two scenes" 2 "$wavefront" merge "$work/a.exr" "$work/t.exr" -o "$work/x.exr"
expect "two scenes: one line" one_line_error
check "not a part" 2 "$wavefront" merge "$work/a.png" -o "$work/x.exr"
expect "not a part: one line" one_line_error
check "merge without output" 2 "$wavefront" merge "$work/a.exr"
expect "nothing written on failure" test ! -e "$work/x.exr"

# --time-limit: far more samples than fit; the EXR and the JSON say how many were done.
check "time limit" 0 "$wavefront" render "$box" -o "$work/limited.exr" --spp 1000000 \
    --width 32 --max-depth 4 --time-limit 1 --json "$work/limited.json"
expect "limit shown in the progress line" grep -q "of a 1 s limit" "$work/stderr"
expect "stopped early, on a whole pass" json_has "$work/limited.json" "1 <= d['spp'] < 1000000"
check "time limit with a finite set" 2 "$wavefront" render "$box" -o "$work/x.exr" \
    --sampler stratified --time-limit 1
expect "finite set: one line" one_line_error

# --aov: the layers as Cycles names its passes (the header names them in plain text).
check "aov layers" 0 "$wavefront" render "$box" -o "$work/aov.exr" --spp 4 --width 24 \
    --max-depth 4 --aov albedo,normal,depth,variance --quiet
for channel in "Denoising Albedo.R" "Denoising Normal.Z" "Depth.Z" "Denoising Variance.B"; do
    expect "aov channel $channel" grep -a -q "$channel" "$work/aov.exr"
done
check "unknown aov" 2 "$wavefront" render "$box" -o "$work/x.exr" --aov albedo,shadow
expect "unknown aov: one line" one_line_error
check "aov twice" 2 "$wavefront" render "$box" -o "$work/x.exr" --aov depth,depth
expect "aov twice: one line" one_line_error

# --target-error: adaptive sampling; the header, the JSON and the progress line say what it
# aimed at and what it reached; flags that need a uniform sample range are refused.
check "target error" 0 "$wavefront" render "$box" -o "$work/adaptive.exr" --target-error 0.02 \
    --spp 256 --width 32 --max-depth 4 --json "$work/adaptive.json" --aov samples,variance
expect "target in the progress line" grep -q "target relMSE 0.02" "$work/stderr"
expect "adaptive json" json_has "$work/adaptive.json" \
    "d['adaptive']['targetError'] == 0.02 and 8 <= d['adaptive']['meanSpp'] < 256 and \
     d['adaptive']['pilotSpp'] == 16 and d['adaptive']['predictedRelMse'] <= 0.02"
expect "adaptive json: the estimate decides targetMet" json_has "$work/adaptive.json" \
    "d['adaptive']['targetMet'] == (d['errorEstimate']['reliable'] and \
     d['errorEstimate']['relMse'] + 4 * d['errorEstimate']['standardError'] <= 0.02) and \
     d['adaptive']['stoppedBy'] in ('target', 'spp', 'rounds') and \
     d['adaptive']['imageRounds'] >= 1"
expect "adaptive json: two error replicates, calibrated" json_has "$work/adaptive.json" \
    "d['errorEstimate']['replicates'] == 2 and d['errorEstimate']['upperBound'] is False"
for attr in targetError targetMet stoppedBy estimatedRelMse errorEstimateReliable meanSpp \
    pilotSpp "Sample Count.Y"; do
    expect "adaptive header: $attr" grep -a -q "$attr" "$work/adaptive.exr"
done
# A target beyond reach: targetMet false, with a warning naming why and what was spent.
check "unreachable target" 0 "$wavefront" render "$box" -o "$work/far.exr" --target-error 1e-9 \
    --spp 32 --width 16 --max-depth 4 --json "$work/far.json"
expect "unreachable target: not met" json_has "$work/far.json" \
    "d['adaptive']['targetMet'] is False and d['adaptive']['stoppedBy'] == 'spp'"
expect "unreachable target: a warning" grep -q "warning: target relMSE 1e-09 not met" "$work/stderr"
# With a time limit, whichever comes first; the JSON says which.
check "target error with a time limit" 0 "$wavefront" render "$box" -o "$work/timed.exr" \
    --target-error 1e-9 --time-limit 1 --spp 100000 --width 16 --max-depth 4 \
    --json "$work/timed.json"
expect "time limit: stopped by it" json_has "$work/timed.json" \
    "d['adaptive']['stoppedBy'] == 'time-limit' and d['adaptive']['targetMet'] is False"
# Every render estimates its own error: JSON, header and the progress line.
check "plain render estimates its error" 0 "$wavefront" render "$box" -o "$work/plain.exr" \
    --spp 16 --width 16 --max-depth 4 --json "$work/plain.json"
expect "plain json: errorEstimate" json_has "$work/plain.json" \
    "d['errorEstimate']['relMse'] > 0 and d['errorEstimate']['upperBound'] is True"
expect "plain header: estimatedRelMse" grep -a -q "estimatedRelMse" "$work/plain.exr"
expect "plain progress line: the estimate" grep -q "relMSE ~" "$work/stderr"
# With error replicates the estimate is calibrated; parts of one sequence merge to a bound.
for part in 0 8; do
    check "replicated part $part" 0 "$wavefront" render "$box" -o "$work/rep$part.exr" \
        --spp 8 --spp-offset $part --spp-total 16 --width 16 --max-depth 4 \
        --error-replicates 2 --json "$work/rep$part.json"
done
expect "replicated json: calibrated" json_has "$work/rep0.json" \
    "d['errorEstimate']['upperBound'] is False and d['errorEstimate']['replicates'] == 2"
expect "replicated header" grep -a -q "errorEstimateReplicates" "$work/rep0.exr"
check "replicated parts merge" 0 "$wavefront" merge "$work/rep0.exr" "$work/rep8.exr" \
    -o "$work/repmerged.exr"
expect "replicated merge: an upper bound" grep -a -q -P \
    'errorEstimateIsUpperBound\x00string\x00\x04\x00\x00\x00true' "$work/repmerged.exr"
expect "replicated part: no bound" grep -a -q -P \
    'errorEstimateIsUpperBound\x00string\x00\x05\x00\x00\x00false' "$work/rep0.exr"
check "error replicates out of range" 2 "$wavefront" render "$box" -o "$work/x.exr" \
    --error-replicates 0
expect "error replicates out of range: one line" one_line_error
for flag in "--spp-offset 8" "--sampler stratified" "--spp 4" \
            "--checkpoint $work/x.exr"; do
    # shellcheck disable=SC2086
    check "target error with $flag" 2 "$wavefront" render "$box" -o "$work/x.exr" \
        --target-error 0.01 $flag
    expect "target error with $flag: one line" one_line_error
done

# Checkpoints: SIGTERM mid-render writes one and ends with 143; resuming it to D + 64 samples
# gives the image of one run of D + 64.
ck="$work/ck.exr"
"$wavefront" render "$box" -o "$work/never.exr" --spp 1000000 --width 24 --max-depth 4 \
    --checkpoint "$ck" --checkpoint-every 0.2 --quiet 2>"$work/interrupted.log" &
pid=$!
# Until the first checkpoint is written, however long that takes.
while [ ! -s "$ck" ] && kill -0 "$pid" 2>/dev/null; do sleep 0.2; done
kill -TERM "$pid"
wait "$pid"
code=$?
expect "SIGTERM ends the render with 143" test "$code" -eq 143
expect "checkpoint written" test -s "$ck"
expect "no output from an interrupted render" test ! -e "$work/never.exr"
done_spp=$(sed -n 's/.*after \([0-9]*\) spp.*/\1/p' "$work/interrupted.log")
expect "the interruption says how far it got" test -n "$done_spp"
target=$(( ${done_spp:-0} + 64 ))
check "resume" 0 "$wavefront" render "$box" -o "$work/resumed.exr" --spp "$target" --width 24 \
    --max-depth 4 --resume "$ck" --quiet
check "uninterrupted run" 0 "$wavefront" render "$box" -o "$work/straight.exr" --spp "$target" \
    --width 24 --max-depth 4 --quiet
check "resumed = uninterrupted" 0 "$compare" "$work/resumed.exr" "$work/straight.exr" \
    --spp "$target" --tolerance 1e-5
check "resume into another seed" 2 "$wavefront" render "$box" -o "$work/x.exr" --spp "$target" \
    --width 24 --max-depth 4 --seed 4 --resume "$ck"
expect "another seed: one line" one_line_error
expect "another seed: named" grep -q "seed 4 differs" "$work/stderr"
check "resume at another size" 2 "$wavefront" render "$box" -o "$work/x.exr" --spp "$target" \
    --width 32 --max-depth 4 --resume "$ck"
expect "another size: one line" one_line_error
check "resume with aov" 2 "$wavefront" render "$box" -o "$work/x.exr" --spp "$target" \
    --width 24 --max-depth 4 --resume "$ck" --aov albedo
expect "resume with aov: one line" one_line_error
check "resume past the target" 2 "$wavefront" render "$box" -o "$work/x.exr" --spp 1 \
    --width 24 --max-depth 4 --resume "$ck"
expect "past the target: one line" one_line_error
finish
