#!/usr/bin/env bash
# The convergence charts (docs/convergence.md): `wavefront converge` on the Cornell box and
# on every failure scene, then the charts copied to
# docs/images/convergence/<scene>_{error_vs_time,error_vs_spp,equal_time}.png.
# Full results (CSV, JSON, crops, reference) stay in OUT (default
# out/convergence). Takes about half an hour on 2 CPU cores with lavapipe.
# Usage: scripts/make_convergence_charts.sh [build/wavefront] [OUT] [SCENE...]
# (with SCENE names, e.g. glass_caustic, only those are redone)
set -euo pipefail
cd "$(dirname "$0")/.."
wavefront=${1:-build/wavefront}
out=${2:-out/convergence}
shift $(($# < 2 ? $# : 2))
only=" $* "
docs=docs/images/convergence
mkdir -p "$out" "$docs"

# Same size, budget and reference for every scene: 64x64, 2 s per method and seed, 5 seeds, a
# reference of 8192 spp rendered by Wavefront with the default method.
converge() { # scene methods
    local scene=$1 methods=$2
    if [ "$only" != "  " ] && [[ "$only" != *" $scene "* ]]; then
        return
    fi
    echo "converge: $scene" >&2
    mkdir -p "$out/$scene"
    "$wavefront" converge "scenes/$scene.gltf" -o "$out/$scene" --width 64 --time 2 \
        --reference-spp 8192 --methods "$methods" --quiet | tee "$out/$scene/ranking.txt"
    for chart in error_vs_time error_vs_spp equal_time; do
        cp "$out/$scene/$chart.png" "$docs/${scene}_$chart.png"
    done
}

samplers=independent,stratified,multijitter,halton,hammersley,sobol,bluenoise
estimators=independent+bsdf,independent+nee,independent+mis,sobol+bsdf,sobol+nee,sobol+mis
converge cornell_box "$samplers,sobol+bsdf,sobol+nee"
converge tiny_light "$estimators"
converge veach_mis "$estimators"
converge glass_caustic "$estimators"
converge many_lamps \
    "sobol+mis+uniform,sobol+mis+power,sobol+mis+tree,independent+mis+power,independent+mis+tree"
converge sphere_near_floor \
    "independent+nee,independent+nee+sphere-area,sobol+nee,sobol+nee+sphere-area,sobol+mis"
echo "charts in $docs, results in $out"
