#!/usr/bin/env bash
# --guiding off|on|auto on the command line (issue 30's interface): the words, auto's decision
# (and that auto's image is --guiding off's, bit for bit, where it decides off), --time-limit
# (training fits the limit), the one-line refusals, and unbiasedness of what combines with the
# guide: a resumed guided render (a checkpoint, then --resume: the resumed part retrains its
# guide) and --spp-offset parts each training their own guide, merged, both against an
# unguided reference per 8x8 region within 5 standard errors over 8 seeds (wf_region_check).
# Usage: test_guiding_cli.sh PATH/TO/wavefront PATH/TO/wf_region_check PATH/TO/scenes
set -u
wavefront=$1
regions=$2
scenes=$3
source "$(dirname "$0")/harness.sh"
box="$scenes/cornell_box.gltf"
caustic="$scenes/glass_caustic.gltf"
small=(--width 32 --max-depth 4 --quiet)

# The words.
check "bad word" 2 "$wavefront" render "$box" -o "$work/x.exr" --guiding yes "${small[@]}"
expect "bad word: one line" one_line_error
check "help lists auto" 0 "$wavefront" render --help
expect "help: --guiding off, on, or auto" grep -q -- "--guiding" "$work/stdout"

# auto: its decision in --verbose and the JSON; where off, the image is --guiding off's.
check "auto verbose" 0 "$wavefront" render "$caustic" -o "$work/auto.exr" --spp 16 --width 32 \
    --max-depth 4 --verbose --json "$work/auto.json"
expect "auto says why" grep -q "guiding auto: off (predicted efficiency" "$work/stderr"
expect "auto in the JSON" json_has "$work/auto.json" "d['guidingDecision'].startswith('auto: off')"
expect "auto compiles no guide" grep -q "WF_GUIDING=0" "$work/stderr"
check "off" 0 "$wavefront" render "$caustic" -o "$work/off.exr" --spp 16 "${small[@]}" --guiding off
check "auto = off, bit for bit" 0 "$regions" --same "$work/auto.exr" "$work/off.exr"
check "auto on an all-mirror-free box" 0 "$wavefront" render "$box" -o "$work/autobox.exr" \
    --spp 16 --width 32 --max-depth 4 --guiding auto --verbose
expect "auto box says diffuse" grep -q "guiding auto: off .*diffuse/glossy" "$work/stderr"

# bench: the guide trains first (untimed), then both kernels time the same frozen guide.
check "bench guided, both kernels" 0 "$wavefront" bench "$caustic" --guiding on \
    --compare-megakernel --width 32 --frames 1 --warmup 0 --max-depth 4 --quiet \
    --json "$work/bench.json"
expect "bench: guided" json_has "$work/bench.json" \
    "d['guiding']['on'] and d['guiding']['trainingSpp'] == 31"
expect "bench: both kernels ran" json_has "$work/bench.json" "len(d['runs']) == 2"
expect "bench says the kernels share the guide" grep -q "both kernels sample the same guide" \
    "$work/stdout"
check "bench auto" 0 "$wavefront" bench "$box" --width 32 --frames 1 --warmup 0 --quiet \
    --json "$work/bench-auto.json"
expect "bench auto: off" json_has "$work/bench-auto.json" "not d['guiding']['on']"

# The Slurm script passes --guiding to every part (a stand-in sbatch runs the job array and
# the merge here, in order).
mkdir -p "$work/bin"
cat >"$work/bin/sbatch" <<'SB'
#!/usr/bin/env bash
array="" script=""
for a in "$@"; do
    case "$a" in --array=*) array=${a#--array=} ;; --*) ;; *) script=$a ;; esac
done
if [ -n "$array" ]; then
    for id in $(seq "${array%-*}" "${array#*-}"); do SLURM_ARRAY_TASK_ID=$id bash "$script" || exit 1; done
    echo 1
else
    bash "$script" >/dev/null 2>&1 || exit 1
    echo 2
fi
SB
chmod +x "$work/bin/sbatch"
check "slurm_render guided" 0 env PATH="$work/bin:$PATH" WAVEFRONT="$wavefront" \
    bash "$(dirname "$0")/../../scripts/slurm_render.sh" "$box" "$work/farm.exr" --parts 2 \
    --spp 16 --guiding on --width 32 --max-depth 4
expect "slurm: merged" test -s "$work/farm.exr"
expect "slurm: parts guided" grep -aq "guidingIterations" "$work/farm.exr.parts/frame_0_part_1.exr"
expect "slurm: the flag reached the parts" grep -q -- "--guiding on" "$work/farm.exr.parts/part.sh"

# --target-error: the guide trains as the pilot (1, 2, 4, ... spp up to the pilot's 4 at
# --spp 64), then the rounds sample it; auto stays off (the budget is unknown before the pilot).
check "on + target-error" 0 "$wavefront" render "$caustic" -o "$work/te.exr" --guiding on \
    --target-error 0.05 --spp 64 --width 32 --max-depth 4 --json "$work/te.json" --verbose
expect "target-error: trained as the pilot" json_has "$work/te.json" \
    "[i['spp'] for i in d['guiding']['iterations']][:3] == [1, 2, 4] and d['adaptive']['pilotSpp'] >= 4"
expect "target-error: training within the image's budget" json_has "$work/te.json" \
    "sum(i['spp'] for i in d['guiding']['iterations']) <= 4 + 0.5 * 64"
expect "target-error: progress names the training" grep -q "training the guide, iteration 3 of 4 spp" \
    "$work/stderr"
expect "target-error: the EXR says guided" grep -aq "guidingIterations" "$work/te.exr"
check "auto + target-error renders unguided" 0 "$wavefront" render "$box" -o "$work/x.exr" \
    --guiding auto --target-error 0.05 --spp 16 "${small[@]}" --verbose
expect "auto + target-error says why" grep -q "guiding auto: off with --target-error" "$work/stderr"

# --time-limit: training keeps at most half of the limit, the image gets samples.
check "on + time-limit" 0 "$wavefront" render "$caustic" -o "$work/tl.exr" --guiding on \
    --spp 100000 --time-limit 4 --width 48 --max-depth 4 --quiet --json "$work/tl.json"
expect "time-limit: trained" json_has "$work/tl.json" "len(d['guiding']['iterations']) >= 1"
# The schedule starts an iteration only where the pace so far says it ends within half of the
# limit. Checked from the JSON's own record of the iterations (the time before iteration i is at
# least the render and rebuild seconds of those before it), so the verdict holds at any speed.
expect "time-limit: every iteration planned within half" json_has "$work/tl.json" \
    "all(sum(j['seconds'] + j['rebuildSeconds'] for j in d['guiding']['iterations'][:i]) *
         (1 + d['guiding']['iterations'][i]['spp'] /
              sum(j['spp'] for j in d['guiding']['iterations'][:i])) <= 0.5 * 4 * (1 + 1e-4)
         for i in range(1, len(d['guiding']['iterations'])))"
expect "time-limit: an image" json_has "$work/tl.json" "d['guiding']['imageSpp'] >= 1"
expect "learnt shares among the candidates" json_has "$work/tl.json" \
    "all(0.499 <= i['bsdfFraction'] <= 1.0 for i in d['guiding']['iterations'])"

# SIGTERM during a guided render (training, for a budget this large) writes a checkpoint of the
# samples done; resuming it trains a guide of its own, and the result is exactly the merge of
# the checkpoint and a guided --spp-offset part over the rest.
ck="$work/gck.exr"
"$wavefront" render "$box" -o "$work/never.exr" --spp 1000000 --guiding on "${small[@]}" \
    --checkpoint "$ck" --checkpoint-every 0.2 2>"$work/interrupted.log" &
pid=$!
# Until the first checkpoint is written, however long that takes (a hang ends the render's
# process or reaches ctest's timeout).
while [ ! -s "$ck" ] && kill -0 "$pid" 2>/dev/null; do sleep 0.2; done
kill -TERM "$pid"
wait "$pid"
code=$?
expect "guided: SIGTERM ends the render with 143" test "$code" -eq 143
done_spp=$(sed -n 's/.*after \([0-9]*\) spp.*/\1/p' "$work/interrupted.log")
expect "guided: the interruption says how far it got" test -n "$done_spp"
target=$(( ${done_spp:-0} + 64 ))
check "guided resume after SIGTERM" 0 "$wavefront" render "$box" -o "$work/gres.exr" \
    --spp "$target" --guiding on "${small[@]}" --resume "$ck"
check "guided rest as a part" 0 "$wavefront" render "$box" -o "$work/grest.exr" --spp 64 \
    --spp-offset "${done_spp:-0}" --guiding on "${small[@]}"
check "merge checkpoint and part" 0 "$wavefront" merge "$ck" "$work/grest.exr" \
    -o "$work/gmerged.exr"
check "resumed = checkpoint + part, bit for bit" 0 "$regions" --same "$work/gres.exr" \
    "$work/gmerged.exr"

# Unbiasedness of the combinations, against an unguided reference.
check "reference" 0 "$wavefront" render "$box" -o "$work/ref.exr" --spp 2048 "${small[@]}" \
    --guiding off --seed 1000
resumed=() merged=()
for seed in 1 2 3 4 5 6 7 8; do
    check "guided checkpoint $seed" 0 "$wavefront" render "$box" -o "$work/half$seed.exr" \
        --spp 16 --guiding on --seed "$seed" --checkpoint "$work/ck$seed.exr" "${small[@]}"
    check "guided resume $seed" 0 "$wavefront" render "$box" -o "$work/res$seed.exr" \
        --spp 32 --guiding on --seed "$seed" --resume "$work/ck$seed.exr" "${small[@]}"
    resumed+=("$work/res$seed.exr")
    check "guided part a $seed" 0 "$wavefront" render "$box" -o "$work/pa$seed.exr" \
        --spp 16 --guiding on --seed "$seed" "${small[@]}"
    check "guided part b $seed" 0 "$wavefront" render "$box" -o "$work/pb$seed.exr" \
        --spp 16 --spp-offset 16 --guiding on --seed "$seed" "${small[@]}"
    check "merge $seed" 0 "$wavefront" merge "$work/pa$seed.exr" "$work/pb$seed.exr" \
        -o "$work/m$seed.exr"
    merged+=("$work/m$seed.exr")
done
check "resumed guided renders are unbiased" 0 "$regions" "$work/ref.exr" "${resumed[@]}"
sed 's/^/  /' "$work/stdout"
check "merged guided parts are unbiased" 0 "$regions" "$work/ref.exr" "${merged[@]}"
sed 's/^/  /' "$work/stdout"
# The check can fail: against a reference without indirect light (--max-depth 1) it does.
check "direct-only reference" 0 "$wavefront" render "$box" -o "$work/direct.exr" --spp 256 \
    --width 32 --max-depth 1 --quiet --guiding off
check "region check fails on a wrong reference" 1 "$regions" "$work/direct.exr" "${merged[@]}"

finish
