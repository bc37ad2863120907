#!/usr/bin/env bash
# `wavefront view` end to end in a real window: Xvfb, the Vulkan device present (lavapipe in
# CI), the validation layer on (any message makes the viewer exit 1, so every run below that
# expects 0 also proves a clean validation log). Checks that
#  - a screenshot after N frames equals `wavefront render` of the same camera, size, spp and
#    seed, and that the PNG of the shown frame is that radiance through the display pass;
#  - after a resize the viewer re-renders at the new size and matches a render of that size;
#  - the moving-camera preview path runs (orbit every frame, a 1 ms frame target);
#  - an animated scene plays (re-posed frame after frame) and, paused at --time, matches render;
#  - SIGTERM quits cleanly: exit 0, screenshot written, no temporary file left;
#  - keys and a mouse drag (xdotool) do what --help says;
#  - --help lists every flag and key; no display or bad flags give one-line errors.
# Without Xvfb or xdotool this fails (scripts/setup.sh --with-tests installs them); it never
# skips.
# Usage: test_viewer.sh PATH/TO/wavefront PATH/TO/wf_compare_images PATH/TO/scenes
set -u
wavefront=$(realpath "$1")
compare=$(realpath "$2")
scenes=$(realpath "$3")
work=$(mktemp -d)
xvfb_pid=""
cleanup() {
    [ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null
    rm -rf "$work"
}
trap cleanup EXIT
failures=0
passes=0
pass() { passes=$((passes + 1)); }
failed() { # failed NAME [LOG]
    echo "FAIL $1"
    [ -n "${2:-}" ] && sed 's/^/  /' "$2" | tail -15
    failures=$((failures + 1))
    # Keep what the failure produced (images, logs) where the developer can look at it.
    mkdir -p "$PWD/viewer_test_failures" && cp -r "$work"/. "$PWD/viewer_test_failures/" 2>/dev/null
}
run() { # run NAME EXPECTED_CODE COMMAND...; output in $work/NAME.log
    local name=$1 expected=$2
    shift 2
    "$@" >"$work/$name.log" 2>&1
    local code=$?
    if [ "$code" -eq "$expected" ]; then
        pass
    else
        failed "$name: exit $code, expected $expected" "$work/$name.log"
    fi
}
check() { # check NAME COMMAND...
    local name=$1
    shift
    if "$@" >"$work/check.log" 2>&1; then
        pass
        grep '^ok' "$work/check.log" # the comparisons' figures
    else
        failed "$name" "$work/check.log"
    fi
}

# wait_for_lines FILE PATTERN N PID: waits until FILE holds N lines matching PATTERN; fails at
# once if process PID ends first, and after 20 minutes, which only a hang reaches.
wait_for_lines() {
    local file=$1 pattern=$2 count=$3 pid=$4
    for _ in $(seq 12000); do
        [ "$(grep -c -- "$pattern" "$file" 2>/dev/null)" -ge "$count" ] && return 0
        kill -0 "$pid" 2>/dev/null || break
        sleep 0.1
    done
    [ "$(grep -c -- "$pattern" "$file" 2>/dev/null)" -ge "$count" ]
}

for tool in Xvfb xdotool; do
    if ! command -v "$tool" >/dev/null; then
        echo "FAIL $tool is not installed; the viewer test needs it:" \
            "bash scripts/setup.sh --with-tests installs it"
        exit 1
    fi
done
# -displayfd picks a free display number and reports it once the server accepts clients.
Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp 3>"$work/display" 2>"$work/xvfb.log" &
xvfb_pid=$!
for _ in $(seq 100); do
    [ -s "$work/display" ] && break
    sleep 0.1
done
if [ ! -s "$work/display" ]; then
    echo "FAIL Xvfb did not start"; sed 's/^/  /' "$work/xvfb.log" | tail -5
    exit 1
fi
export DISPLAY=":$(head -n1 "$work/display")"
export WAVEFRONT_VALIDATION=1
cornell="$scenes/cornell_box.gltf"
common=(--spp 8 --seed 7 --max-depth 6)
# --until-done: each run below quits when its image reaches --spp, however many frames that
# takes on a busy machine. A generous frame-time target keeps those frames few (whole samples);
# partial samples per frame are checked bit for bit by the GPU tests.
slow=(--target-ms 5000)

# 1. Same image as render at the 8-spp limit.
run "view" 0 "$wavefront" view "$cornell" "${common[@]}" "${slow[@]}" --width 128 --height 96 \
    --until-done \
    --no-overlay --screenshot "$work/view.exr"
run "render" 0 "$wavefront" render "$cornell" "${common[@]}" --width 128 --height 96 \
    -o "$work/render.exr" --quiet
check "view matches render" "$compare" "$work/view.exr" "$work/render.exr" --spp 8 \
    --shown "$work/view.png"

# --traversal rt where the device has ray-tracing pipelines (Mesa 25's lavapipe): the viewer's
# context enables them and its image is render's with the same traversal.
if "$wavefront" render "$cornell" --width 8 --spp 1 --traversal rt -o "$work/probe.exr" \
    --quiet 2>/dev/null; then
    run "view-rt" 0 "$wavefront" view "$cornell" "${common[@]}" "${slow[@]}" --traversal rt \
        --width 128 --height 96 --until-done --no-overlay --screenshot "$work/view-rt.exr"
    run "render-rt" 0 "$wavefront" render "$cornell" "${common[@]}" --traversal rt \
        --width 128 --height 96 -o "$work/render-rt.exr" --quiet
    check "rt view matches rt render" "$compare" "$work/view-rt.exr" "$work/render-rt.exr" \
        --spp 8
fi

# Bidirectional path tracing: whole samples per frame, the same image as render's.
run "view-bdpt" 0 "$wavefront" view "$cornell" "${common[@]}" "${slow[@]}" --integrator bdpt \
    --width 64 --height 48 --until-done --no-overlay --screenshot "$work/view-bdpt.exr"
run "render-bdpt" 0 "$wavefront" render "$cornell" "${common[@]}" --integrator bdpt \
    --width 64 --height 48 -o "$work/render-bdpt.exr" --quiet
check "bdpt view matches bdpt render" "$compare" "$work/view-bdpt.exr" "$work/render-bdpt.exr" \
    --spp 8

# Hero wavelengths (--spectral hero) through the rough dispersive prism: render's image.
run "view-hero" 0 "$wavefront" view "$scenes/prism_rough.gltf" "${common[@]}" "${slow[@]}" \
    --spectral hero --width 64 --height 48 --until-done --no-overlay \
    --screenshot "$work/view-hero.exr"
run "render-hero" 0 "$wavefront" render "$scenes/prism_rough.gltf" "${common[@]}" \
    --spectral hero --width 64 --height 48 -o "$work/render-hero.exr" --quiet
check "hero view matches hero render" "$compare" "$work/view-hero.exr" \
    "$work/render-hero.exr" --spp 8

# A finite-set sampler: the viewer's set is its --spp, as render's is.
run "view-stratified" 0 "$wavefront" view "$cornell" "${common[@]}" "${slow[@]}" \
    --sampler stratified \
    --width 128 --height 96 --until-done --screenshot "$work/stratified.exr"
run "render-stratified" 0 "$wavefront" render "$cornell" "${common[@]}" --sampler stratified \
    --width 128 --height 96 -o "$work/render-stratified.exr" --quiet
check "stratified view matches render" "$compare" "$work/stratified.exr" \
    "$work/render-stratified.exr" --spp 8

# 2. Resize after frame 3: the accumulation restarts at the new size and reaches 8 spp again
#    (--until-done waits for the window to take the new size).
run "resize" 0 "$wavefront" view "$cornell" "${common[@]}" "${slow[@]}" --width 128 --height 96 \
    --resize-at 3:160x120 --until-done --screenshot "$work/resized.exr"
run "render-resized" 0 "$wavefront" render "$cornell" "${common[@]}" --width 160 --height 120 \
    -o "$work/render-resized.exr" --quiet
check "resized view matches render" "$compare" "$work/resized.exr" "$work/render-resized.exr" \
    --spp 8

# 2b. --guiding on: the guide trains while the image refines (the image restarts after 1, 2,
# 4, ... spp, each training iteration holding exactly its samples whatever a frame's budget);
# the default, auto, decided off for the Cornell box above (the same image as render). The
# overlay's --guiding switch rebuilds the renderer as --max-depth's does.
run "guided" 0 "$wavefront" view "$cornell" --guiding on "${common[@]}" "${slow[@]}" \
    --spp 16 --width 64 --height 48 --until-done --screenshot "$work/guided.exr"
check "guided screenshot written" test -s "$work/guided.exr" -a -s "$work/guided.png"
# The Cornell box's leaves learn BSDF share 1, so training stops after 1 + 2 + 4 + 8 spp
# (guiding::UnusedGuideStop), and the last of the 16 spp is the unguided image's.
check "guided view trained while refining" grep -q \
    "guide: unused (no leaf's share paid) after 15 spp of training" "$work/guided.log"
# A 1 ms target splits every sample over many frames: the same schedule, the same image.
run "guided-split" 0 "$wavefront" view "$cornell" --guiding on "${common[@]}" --target-ms 1 \
    --spp 16 --width 16 --height 12 --until-done --no-overlay --screenshot "$work/guided-split.exr"
run "guided-whole" 0 "$wavefront" view "$cornell" --guiding on "${common[@]}" "${slow[@]}" \
    --spp 16 --width 16 --height 12 --until-done --no-overlay --screenshot "$work/guided-whole.exr"
check "guided view: the same image at any frame budget" "$compare" "$work/guided-split.exr" \
    "$work/guided-whole.exr" --spp 16
check "guided view: the same schedule at any frame budget" bash -c \
    "grep 'guide:' '$work/guided-split.log' && grep 'guide:' '$work/guided-split.log' |
     cmp - <(grep 'guide:' '$work/guided-whole.log')"

# 3. Orbiting every frame with a 1 ms target: the low-resolution preview is drawn and scaled.
run "orbit" 0 "$wavefront" view "$cornell" --width 256 --height 192 --orbit 10 --frames 6 \
    --target-ms 1 --screenshot "$work/orbit.exr"
check "orbit screenshot written" test -s "$work/orbit.png"
check "orbit drew previews" grep -Eq "frames \([1-9][0-9]* previews\)" "$work/orbit.log"

# 3b. Playback of an animated scene (--play, as T does): the scene is re-posed frame after
#     frame under the same renderers (validation stays clean); paused at --time 0.5, the
#     screenshot is render --time 0.5's image.
arm="$scenes/animated_arm.gltf"
run "play" 0 "$wavefront" view "$arm" --play --frames 12 --width 96 --target-ms 5 \
    --screenshot "$work/play.exr"
check "play re-posed the scene" grep -Eq "[1-9][0-9]* poses of the animation shown" \
    "$work/play.log"
run "view-time" 0 "$wavefront" view "$arm" "${common[@]}" "${slow[@]}" --time 0.5 \
    --width 96 --height 64 --until-done --no-overlay --screenshot "$work/time.exr"
run "render-time" 0 "$wavefront" render "$arm" "${common[@]}" --time 0.5 --width 96 \
    --height 64 -o "$work/render-time.exr" --quiet
check "view --time matches render --time" "$compare" "$work/time.exr" "$work/render-time.exr" \
    --spp 8

# 3c. KHR_materials_variants: view --variant shows render --variant's image.
python3 "$(dirname "$0")/../cli/variants_gltf.py" "$work/variants.gltf"
run "view-variant" 0 "$wavefront" view "$work/variants.gltf" "${common[@]}" "${slow[@]}" \
    --variant blue --width 64 --height 64 --until-done --no-overlay \
    --screenshot "$work/variant.exr"
run "render-variant" 0 "$wavefront" render "$work/variants.gltf" "${common[@]}" \
    --variant blue --width 64 --height 64 -o "$work/render-variant.exr" --quiet
check "view --variant matches render --variant" "$compare" "$work/variant.exr" \
    "$work/render-variant.exr" --spp 8
run "view-bad-variant" 2 "$wavefront" view "$work/variants.gltf" --variant green --frames 1

# 4. SIGTERM while refining: a clean quit that still writes the screenshot atomically.
"$wavefront" view "$cornell" --width 128 --height 96 --screenshot "$work/term.exr" \
    >"$work/term.log" 2>&1 &
viewer=$!
wait_for_lines "$work/term.log" "viewing" 1 "$viewer"
kill -TERM "$viewer"
wait "$viewer"
code=$?
if [ "$code" -eq 0 ]; then pass; else failed "SIGTERM: exit $code, expected 0" "$work/term.log"; fi
check "SIGTERM screenshot written" test -s "$work/term.exr" -a -s "$work/term.png"
check "no temporary files left" bash -c "! ls '$work' | grep -q tmp"

# 5. Keys and mouse as a person uses them (xdotool): P and F12 save numbered screenshots, a
#    left drag orbits (the image changes), R returns to the starting view (the same image
#    again, bit for bit), Esc quits with 0. Each step waits for the viewer's own line saying
#    the last one took effect (the image refined to its 4 spp, a screenshot written), never for
#    a time: drags are gathered from the window's events, so even a press, move and release
#    within one slow frame orbit.
(
    cd "$work" || exit 1
    "$wavefront" view "$cornell" "${common[@]}" --spp 4 --width 128 --height 96 --no-overlay \
        >"$work/keys.log" 2>&1 &
    viewer=$!
    step() { # step N PATTERN: wait until the log holds N lines matching PATTERN
        wait_for_lines "$work/keys.log" "$2" "$1" "$viewer" && return 0
        echo "keys: no $1 lines '$2' in the log"
        kill "$viewer" 2>/dev/null
        exit 1
    }
    step 1 "viewing"
    window=$(xdotool search --name "Wavefront - cornell_box.gltf" | head -n1)
    if [ -z "$window" ]; then
        kill "$viewer"
        exit 1
    fi
    xdotool windowfocus --sync "$window"
    step 1 "refined to 4 spp"
    xdotool key --window "$window" p
    step 1 "wavefront: wrote "
    # One xdotool call: press, move and release usually reach the viewer within one frame.
    xdotool mousemove --window "$window" 40 48 mousedown 1 mousemove --window "$window" 90 40 \
        mouseup 1
    step 2 "refined to 4 spp"
    xdotool key --window "$window" F12
    step 2 "wavefront: wrote "
    xdotool key --window "$window" r
    step 3 "refined to 4 spp"
    xdotool key --window "$window" p
    step 3 "wavefront: wrote "
    xdotool key --window "$window" Escape
    wait "$viewer"
) >"$work/xdotool.log" 2>&1
code=$?
if [ "$code" -eq 0 ]; then pass; else failed "keys: exit $code" "$work/xdotool.log"; fi
shots="$work/cornell_box"
check "keys: three screenshots" \
    test -s "$shots-001.png" -a -s "$shots-002.exr" -a -s "$shots-003.exr"
check "keys: R returns to the start view" "$compare" "$shots-003.exr" "$shots-001.exr" --spp 4
check "keys: after the drag, 4 spp again" "$compare" "$shots-002.exr" "$shots-002.exr" --spp 4
check "keys: the drag moved the camera" bash -c "! '$compare' '$shots-002.exr' '$shots-001.exr'"

# 6. Command-line contract.
run "help" 0 "$wavefront" view --help
for word in --width --height --spp --max-depth --rr-depth --light-sampling \
    --triangle-sampling --sphere-sampling --min-throughput --clamp --env --seed --sampler \
    --exposure --tonemap --target-ms --camera --no-overlay --device --frames --until-done --screenshot \
    --resize-at --orbit --play --quiet F12 Space Esc orbit pan dolly fly; do
    check "view help lists $word" grep -q -- "$word" "$work/help.log"
done
run "no display" 1 env -u DISPLAY -u WAYLAND_DISPLAY "$wavefront" view "$cornell" --frames 1
check "no display: one line naming xvfb-run" \
    bash -c "[ \$(wc -l <'$work/no display.log') -eq 1 ] && grep -q xvfb-run '$work/no display.log'"
run "bad tonemap" 2 "$wavefront" view "$cornell" --tonemap filmic
run "bad resize" 2 "$wavefront" view "$cornell" --resize-at 3x4
run "bad camera" 2 "$wavefront" view "$cornell" --camera 7 --frames 1
run "framing camera" 0 "$wavefront" view "$cornell" --camera 1 --frames 2 --width 64 --quiet

echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ]
