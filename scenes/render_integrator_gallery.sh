#!/usr/bin/env bash
# Renders the integrators' gallery (README, docs/bidirectional.md): each scene with each
# --integrator for the same seconds (render --time-limit), 160 pixels wide, max depth 8:
# docs/images/integrators/<scene>_<integrator>.png. Equal time is only fair on a quiet
# machine. Usage: scenes/render_integrator_gallery.sh [build/wavefront] [seconds]
set -euo pipefail
cd "$(dirname "$0")/.."
wavefront=${1:-build/wavefront}
seconds=${2:-6}
out=docs/images/integrators
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# bench/mitsuba_peer.py's mirror + glass box, written as it writes it.
python3 -c "import sys; sys.path.insert(0, 'bench'); import mitsuba_peer as m; \
m.write_scene('mirror-glass', '$tmp')" > /dev/null
mirror_glass=$(ls "$tmp"/*.gltf | head -1)
for entry in "caustic:scenes/glass_caustic.gltf" "mirror_glass:$mirror_glass" \
             "mirror_caustic:scenes/mirror_caustic.gltf" "veach:scenes/veach_mis.gltf"; do
    name=${entry%%:*}
    scene=${entry#*:}
    for integrator in path light bdpt vcm; do
        # Untimed first: llvmpipe compiles a pipeline's code at its first dispatch, which a
        # time-limited render would count.
        "$wavefront" render "$scene" -o "$tmp/warm.exr" --width 160 --max-depth 8 --spp 1 \
            --integrator "$integrator" --quiet
        "$wavefront" render "$scene" -o "$tmp/$name-$integrator.exr" --width 160 --max-depth 8 \
            --spp 65536 --time-limit "$seconds" --seed 1 --integrator "$integrator" \
            --json "$tmp/$name-$integrator.json" --quiet
        mv "$tmp/$name-$integrator.png" "$out/${name}_$integrator.png"
        python3 -c "import json; d = json.load(open('$tmp/$name-$integrator.json')); \
print('$name $integrator', d.get('spp'), 'spp in', round(d.get('seconds', 0), 1), 's')"
    done
done
