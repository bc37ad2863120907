#!/usr/bin/env bash
# Renders each failure scene with each method at equal samples for the README's gallery:
# docs/images/failures/<scene>_<method>.png, and three frames of the animated scene
# (docs/images/animation/) and one through a shutter (motion blur). Usage: scenes/render_gallery.sh [build/wavefront]
set -euo pipefail
cd "$(dirname "$0")/.."
wavefront=${1:-build/wavefront}
out=docs/images/failures
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
render() { # scene method flags...
    local scene=$1 method=$2
    shift 2
    "$wavefront" render "scenes/$scene.gltf" -o "$tmp/$scene-$method.exr" --width 200 --spp 16 \
        --seed 1 --quiet "$@"
    mv "$tmp/$scene-$method.png" "$out/${scene}_$method.png"
}
for scene in tiny_light veach_mis glass_caustic; do
    render "$scene" bsdf --light-sampling bsdf
    render "$scene" nee --light-sampling nee
    render "$scene" mis --light-sampling mis
done
for selection in uniform power tree; do
    render many_lamps "$selection" --light-selection "$selection"
done
render sphere_near_floor area --light-sampling nee --sphere-sampling area
render sphere_near_floor solid-angle --light-sampling nee --sphere-sampling solid-angle
# Path guiding (issue 30) against unguided MIS, 64 spp each (the guided one's training
# iterations among them).
for method in mis guided; do
    "$wavefront" render scenes/narrow_gap.gltf -o "$tmp/narrow_gap-$method.exr" --width 200 \
        --spp 64 --seed 1 --quiet --guiding "$([ "$method" = guided ] && echo on || echo off)"
    mv "$tmp/narrow_gap-$method.png" "$out/narrow_gap_$method.png"
done
echo "wrote $(ls "$out" | wc -l) images to $out"
# KHR_materials_diffuse_transmission beside the same paper without it (docs/gltf.md).
mkdir -p docs/images/materials
"$wavefront" render scenes/lamp_shades.gltf -o "$tmp/lamp_shades.exr" --width 300 --spp 256 \
    --seed 1 --quiet
mv "$tmp/lamp_shades.png" docs/images/materials/lamp_shades.png
# KHR_materials_dispersion: a prism's rainbow (docs/gltf.md).
"$wavefront" render scenes/prism.gltf -o "$tmp/prism.exr" --width 300 --spp 2048 --seed 1 --quiet
mv "$tmp/prism.png" docs/images/materials/prism.png
# Each extension's material beside the same without it (scenes/make_material_pairs.py).
for pair in anisotropy:256 iridescence:256 dispersion:1024; do
    name=${pair%%:*}
    "$wavefront" render "scenes/${name}_pair.gltf" -o "$tmp/${name}_pair.exr" --width 320 \
        --spp "${pair#*:}" --max-depth 8 --seed 1 --quiet
    mv "$tmp/${name}_pair.png" "docs/images/materials/${name}_pair.png"
done
# The animated scene at three times (render --frames: frames 0, 12 and 24 at 24 fps).
anim=docs/images/animation
mkdir -p "$anim"
"$wavefront" render scenes/animated_arm.gltf --frames 0..24:12 -o "$tmp/arm_%04d.exr" \
    --width 300 --spp 64 --seed 1 --quiet
for f in 0000 0012 0024; do mv "$tmp/arm_$f.png" "$anim/arm_$f.png"; done
# Frame 12 again through a shutter of 4 frames (1/6 s at 24 fps): motion blur.
"$wavefront" render scenes/animated_arm.gltf --frame 12 --shutter -2:2 -o "$tmp/arm_blur.exr" \
    --width 300 --spp 256 --seed 1 --quiet 2>/dev/null
mv "$tmp/arm_blur.png" "$anim/arm_0012_shutter.png"
echo "wrote 4 frames to $anim"
