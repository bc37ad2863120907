#!/usr/bin/env bash
# The command line on real and broken scenes: every invalid corpus file is refused with exit
# code 2, one line on stderr and no output file; --camera and --env choose and refuse cleanly;
# textured scenes render; a generated scene of over 300k triangles renders with its BVH
# statistics in --verbose; one of 3 M triangles, over one buffer's limit, renders; a mesh placed
# to 3 M triangles is kept once and instanced (--instancing), and flattened with off.
# Usage: test_cli_scenes.sh PATH/TO/wavefront SOURCE_DIR
set -u
wavefront=$1
source_dir=$2
corpus=$source_dir/tests/gltf_corpus
source "$(dirname "$0")/harness.sh"
render() { "$wavefront" render "$@" --spp 1 --width 24 --max-depth 2 --quiet; }

for file in "$corpus"/invalid/*.gl*; do
    name=invalid/$(basename "$file")
    check "$name" 2 render "$file" -o "$work/out.exr"
    expect "$name: one line" one_line_error
    expect "$name: names the file" grep -qF "$file" "$work/stderr"
    expect "$name: no output" test ! -e "$work/out.exr" -a ! -e "$work/out.png"
done

check "help" 0 "$wavefront" render --help
for flag in --camera --env --verbose; do
    expect "help lists $flag" grep -q -- "$flag" "$work/stdout"
done
for file in texture_png.gltf texture_jpeg_in_bufferview.glb alpha_mask_all_textures.gltf \
            normal_map_generated_tangents.gltf lights_punctual_and_sphere.gltf; do
    check "valid/$file renders" 0 render "$corpus/valid/$file" -o "$work/$file.exr"
    expect "valid/$file: image" test -s "$work/$file.png"
done
cameras=$corpus/valid/cameras_some_invalid.gltf
check "--camera by name" 0 render "$cameras" -o "$work/cam.exr" --camera cam3
check "--camera by index" 0 render "$cameras" -o "$work/cam.exr" --camera 1
check "an orthographic camera" 0 render "$corpus/valid/camera_orthographic.gltf" -o "$work/ortho.exr"
check "--aperture with an orthographic camera" 2 render "$corpus/valid/camera_orthographic.gltf" \
    -o "$work/noortho.exr" --aperture 0.1
expect "--aperture with an orthographic camera: one line" one_line_error
check "--camera unknown" 2 render "$cameras" -o "$work/nocam.exr" --camera side
expect "--camera unknown: one line" one_line_error
expect "--camera unknown: lists cameras" grep -q "'front'" "$work/stderr"
expect "--camera unknown: no output" test ! -e "$work/nocam.exr"
check "--env" 0 render "$corpus/valid/triangle.gltf" -o "$work/env.exr" --env "$work/cam.exr"
printf 'v/1\001 this is not an EXR' >"$work/broken.exr"
check "--env broken" 2 render "$corpus/valid/triangle.gltf" -o "$work/noenv.exr" \
    --env "$work/broken.exr"
expect "--env broken: one line" one_line_error
check "--env missing" 2 render "$corpus/valid/triangle.gltf" -o "$work/noenv.exr" \
    --env "$work/none.exr"
expect "--env missing: one line" one_line_error

python3 "$source_dir/scenes/make_big_scene.py" "$work/big.glb" >/dev/null
check "big scene renders" 0 "$wavefront" render "$work/big.glb" -o "$work/big.exr" --spp 1 \
    --width 48 --max-depth 2 --verbose
triangles=$(grep -o '[0-9]* triangles, [0-9]* materials, [0-9]* emitters' "$work/stderr" |
            head -1 | cut -d' ' -f1)
expect "big scene has >= 300k triangles ($triangles)" test "${triangles:-0}" -ge 300000
expect "big scene: BVH build time and SAH cost" grep -q "SAH cost .*built in" "$work/stderr"
expect "big scene: vertex normals buffer" grep -q "vertex normals" "$work/stderr"

# Over one buffer's limit on lavapipe (128 MiB: 2.8 M triangles of 48 bytes): the triangle
# table spreads over two buffers and the scene renders.
python3 "$source_dir/bench/make_scaling_scene.py" "$work/over.gltf" --triangles 3000000 >/dev/null
check "scene over one buffer renders" 0 "$wavefront" render "$work/over.gltf" \
    -o "$work/over.exr" --spp 1 --width 16 --max-depth 2 --verbose --json "$work/over.json" \
    --instancing off
if grep -q "device llvmpipe" "$work/stderr"; then # other devices may hold it in one buffer
    expect "over one buffer: a second triangle page" grep -q "triangles page 2" "$work/stderr"
fi
expect "over one buffer: all its triangles" json_has "$work/over.json" "d['triangles'] > 2900000"
expect "over one buffer: flattened" json_has "$work/over.json" "d['instances'] == 0"

# One 100k-triangle pebble placed ~30 times beside a small scene: instanced by default.
python3 "$source_dir/bench/make_scaling_scene.py" "$work/pebbles.gltf" --triangles 2000 \
    --instanced-triangles 3000000 >/dev/null
check "instanced scene renders" 0 "$wavefront" render "$work/pebbles.gltf" \
    -o "$work/pebbles.exr" --spp 1 --width 16 --max-depth 2 --verbose --json "$work/pebbles.json"
expect "instanced: two-level BVH in --verbose" grep -q "two-level BVH: 3[0-9] instances" "$work/stderr"
expect "instanced: unique triangles" json_has "$work/pebbles.json" "d['triangles'] < 110000"
expect "instanced: placed triangles" json_has "$work/pebbles.json" "d['instancedTriangles'] > 2900000"
expect "instanced: instances" json_has "$work/pebbles.json" "d['instances'] >= 30"
check "--instancing refuses a bad mode" 2 "$wavefront" render "$work/pebbles.gltf" \
    -o "$work/bad.exr" --instancing sometimes
expect "--instancing: names the modes" grep -q "auto, on or off" "$work/stderr"

finish
