#!/usr/bin/env bash
# Renders Khronos' sample models for the material extensions (issue 48) into
# docs/images/khronos/NAME.png and reports every "ignoring" warning in the logs.
#
#   scripts/render_khronos_models.sh MODELS_DIR [OUT_DIR]
#
# MODELS_DIR holds the models in glTF-Sample-Assets' layout (MODELS_DIR/NAME/glTF/NAME.gltf,
# or glTF-Binary/NAME.glb); a model that is not there is skipped and said so. The models are
# third-party files: keep them out of the repository. Small renders (256 px wide, 128 spp,
# max depth 8), each under nice. Environment: WAVEFRONT (the binary, default build/wavefront),
# SPP, WIDTH, ENV (an equirectangular .exr for --env; without it scenes that emit nothing get
# the CLI's uniform white, and the two lamps are lit by their bulbs alone), EXTRA (more render
# options), LOG_DIR (keep each model's --verbose log there as NAME.log), QUANTIZE (1, the
# default: the PNGs are brought to 256 colours, about 45 KB instead of 155 KB, by a python3
# with PIL where there is one; 0 keeps the renderer's preview as it is).
# docs/images/khronos/ was made with the environment of the glTF Render Fidelity goldens:
#   git show HEAD:public/env_maps/chinese_garden_1k.hdr > garden.hdr   (in that repository)
#   scripts/hdr_to_exr.py garden.hdr garden.exr --roll 0.5
#   ENV=garden.exr scripts/render_khronos_models.sh MODELS_DIR
set -u
here="$(cd "$(dirname "$0")/.." && pwd)"
models="${1:?usage: $0 MODELS_DIR [OUT_DIR]}"
out="${2:-$here/docs/images/khronos}"
bin="${WAVEFRONT:-$here/build/wavefront}"
spp="${SPP:-128}"
width="${WIDTH:-256}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"

names=(AnisotropyBarnLamp AnisotropyRotationTest AnisotropyStrengthTest IridescenceLamp
       IridescenceSuzanne DispersionTest DragonDispersion DiffuseTransmissionTest
       DiffuseTransmissionPlant MaterialsVariantsShoe ClearCoatTest SheenChair
       AttenuationTest SimpleInstancing)

pil=""
if [ "${QUANTIZE:-1}" != 0 ]; then
    for py in python3 /usr/bin/python3; do
        if command -v "$py" >/dev/null && "$py" -c 'import PIL' 2>/dev/null; then pil="$py"; break; fi
    done
fi

status=0
for name in "${names[@]}"; do
    scene=""
    for cand in "$models/$name/glTF/$name.gltf" "$models/$name/glTF-Binary/$name.glb" \
                "$models/$name.gltf" "$models/$name.glb"; do
        [ -f "$cand" ] && { scene="$cand"; break; }
    done
    if [ -z "$scene" ]; then
        echo "$name: not found under $models, skipped"
        continue
    fi
    envopt=()
    [ -n "${ENV:-}" ] && envopt=(--env "$ENV")
    # shellcheck disable=SC2086
    if nice "$bin" render "$scene" -o "$work/$name.exr" --width "$width" --spp "$spp" \
            --max-depth 8 --verbose "${envopt[@]}" ${EXTRA:-} 2> "$work/$name.log"; then
        if [ -n "$pil" ]; then
            "$pil" -c 'import sys; from PIL import Image
Image.open(sys.argv[1]).convert("RGB").quantize(256).save(sys.argv[2], optimize=True)' \
                "$work/$name.png" "$out/$name.png"
        else
            cp "$work/$name.png" "$out/$name.png"
        fi
        if grep -qi "ignoring" "$work/$name.log"; then
            echo "$name: rendered, WARNINGS:"
            grep -i "ignoring" "$work/$name.log" | sed 's/^/    /'
            status=1
        else
            echo "$name: rendered, no 'ignoring' warning"
        fi
    else
        echo "$name: FAILED (log below)"
        tail -n 20 "$work/$name.log" | sed 's/^/    /'
        status=1
    fi
    if [ -n "${LOG_DIR:-}" ]; then mkdir -p "$LOG_DIR" && cp "$work/$name.log" "$LOG_DIR/"; fi
done
exit $status
