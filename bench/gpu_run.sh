#!/usr/bin/env bash
# The prepared GPU run (issue 34): on a GPU machine with nothing installed, render the gallery
# scenes and run the benches with --traversal bvh and rt, writing JSON under bench/results/, in
# well under 8 minutes. Two steps:
#
#   bash bench/gpu_run.sh prepare [build/wavefront]
#       here, on the build machine: copies the binary and the shared libraries it loads (ldd,
#       glibc's own left out) into .gpu/, and downloads the Vulkan loader package (libvulkan1)
#       into .gl/ as DEVELOPERS.md's GPU note says; both folders are git-ignored and travel
#       with the working tree when named in the device run's `carry` (about 40 MiB).
#   bash bench/gpu_run.sh run [--small]
#       there (or here, as a dry run on lavapipe with --small): unpacks the loader where none
#       is installed, points Vulkan at the NVIDIA driver where the loader finds none, then
#         1. renders the gallery scenes with each traversal (512 wide, 64 spp; --small: 96, 8),
#         2. benches the Cornell box, the 300k-triangle mesh and the instanced spheres
#            (bench/mitsuba_peer.py's scenes) with bvh and rt in alternating pairs,
#         3. runs bench/scaling.sh --no-large with SCALING_TRAVERSAL=bvh, then rt,
#       and with $OUT set (the device tool) packs bench/results/<label>_* into one tarball there.
#       Each step is skipped once 7 minutes have passed. Label: GPU_RUN_LABEL (default gpu, or
#       dryrun with --small).
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
mode=${1:-run}

if [ "$mode" = prepare ]; then
    binary=${2:-$root/build/wavefront}
    bundle=$root/.gpu
    rm -rf "$bundle" && mkdir -p "$bundle/lib"
    cp "$binary" "$bundle/wavefront"
    # Every library the binary loads but glibc's (the GPU image's own, newer, must serve), and
    # the Vulkan loader, which comes from its package below.
    ldd "$binary" | awk '$3 ~ /^\// {print $3}' | while read -r lib; do
        case "$(basename "$lib")" in
        libc.so* | libm.so* | libpthread.so* | libdl.so* | librt.so* | ld-linux* | libvulkan.so*) ;;
        # C++'s runtime is backward compatible: the GPU image's own (newer, and what its
        # driver may need) serves where it has one; these copies only where it has none.
        libstdc++.so* | libgcc_s.so*) mkdir -p "$bundle/fallback" && cp -L "$lib" "$bundle/fallback/" ;;
        *) cp -L "$lib" "$bundle/lib/" ;;
        esac
    done
    mkdir -p "$root/.gl" /tmp/amd64/partial
    apt_options=(-oAPT::Architecture=amd64 -oAPT::Architectures=amd64
                 -oDir::State::Lists=/tmp/amd64)
    if ! { apt-get "${apt_options[@]}" update -qq &&
           (cd "$root/.gl" && apt-get "${apt_options[@]}" download -qq libvulkan1); }; then
        echo "gpu_run: warning: libvulkan1 not downloaded; carrying this machine's loader" >&2
        ldd "$binary" | awk '$3 ~ /libvulkan/ {print $3}' | xargs -r -I{} cp -L {} "$bundle/lib/"
    fi
    du -sh "$bundle" "$root/.gl" | sed 's/^/gpu_run: /'
    echo "gpu_run: carry [\".gpu\", \".gl\"] and run: bash bench/gpu_run.sh run"
    exit 0
fi
[ "$mode" = run ] || { echo "usage: gpu_run.sh prepare [binary] | run [--small]" >&2; exit 2; }
small=0
[ "${2:-}" = --small ] && small=1
label=${GPU_RUN_LABEL:-$([ "$small" = 1 ] && echo dryrun || echo gpu)}
budget=420 # seconds: stop starting steps past 7 minutes
results=$here/results
mkdir -p "$results"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The binary: the carried bundle where there is one, else this checkout's build.
if [ -x "$root/.gpu/wavefront" ]; then
    wavefront=$root/.gpu/wavefront
    libs=$root/.gpu/lib
    for lib in "$root"/.gpu/fallback/*; do
        [ -e "$lib" ] || continue
        ldconfig -p 2>/dev/null | grep -q "$(basename "$lib") " || libs=$libs:$root/.gpu/fallback
    done
    export LD_LIBRARY_PATH="$libs${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
else
    wavefront=${WAVEFRONT:-$root/build/wavefront}
fi
if ! ldconfig -p 2>/dev/null | grep -q 'libvulkan.so.1 ' && ls "$root"/.gl/*.deb >/dev/null 2>&1; then
    for f in "$root"/.gl/*.deb; do dpkg -x "$f" /; done
    ldconfig
fi
nvidia_icd=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
if [ -z "${VK_DRIVER_FILES:-}${VK_ICD_FILENAMES:-}" ] && [ -f "$nvidia_icd" ]; then
    export VK_DRIVER_FILES=$nvidia_icd
fi
export WAVEFRONT_SHADER_DIR=$root/shaders WAVEFRONT_CACHE_DIR=$work/spirv

log() { echo "gpu_run: [$SECONDS s] $*"; }
in_time() { [ "$SECONDS" -lt "$budget" ] || { log "skipped (past ${budget} s): $*"; return 1; }; }
"$wavefront" render "$root/scenes/cornell_box.gltf" -o "$work/probe.exr" --width 16 --spp 1 \
    --traversal rt -q --json "$work/probe.json" 2>"$work/probe.err"
if [ $? -eq 0 ]; then
    traversals="bvh rt"
else
    traversals="bvh"
    log "no rt on this device: $(cat "$work/probe.err")"
fi
log "device: $(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["device"])' \
    "$work/probe.json" 2>/dev/null || echo unknown); traversals: $traversals"

# 1. The gallery scenes, each traversal.
width=512 spp=64
[ "$small" = 1 ] && width=96 spp=8
for scene in cornell_box tiny_light veach_mis glass_caustic many_lamps sphere_near_floor; do
    in_time "gallery $scene" || break
    for t in $traversals; do
        "$wavefront" render "$root/scenes/$scene.gltf" -o "$work/$scene-$t.exr" --width "$width" \
            --spp "$spp" --seed 1 -q --traversal "$t" \
            --json "$results/${label}_gallery_${scene}_$t.json" || log "render $scene $t failed"
    done
done
log "gallery done"

# 2. Three scenes, bvh and rt in alternating pairs (the closing note's table).
frames=4 pairs=3 bench_width=256
[ "$small" = 1 ] && frames=1 pairs=1 bench_width=64
python3 "$here/make_scaling_scene.py" "$work/mesh.gltf" --triangles 300000 --materials 1 \
    >/dev/null || log "mesh scene not written"
python3 - "$work" "$here" <<'PY' || log "instanced scene not written (numpy missing?)"
import sys
sys.path.insert(0, sys.argv[2])
import mitsuba_peer  # its scene writers; it imports numpy
mitsuba_peer.write_scene("instances", sys.argv[1])
PY
cp "$root/scenes/cornell_box.gltf" "$work/cornell.gltf"
for scene in cornell mesh instances; do
    [ -f "$work/$scene.gltf" ] || continue
    for pair in $(seq 1 "$pairs"); do
        for t in $traversals; do
            in_time "bench $scene $t" || break 3
            "$wavefront" bench "$work/$scene.gltf" --width "$bench_width" --frames "$frames" \
                --max-depth 8 --warmup 1 -q --traversal "$t" \
                --json "$results/${label}_traversal_${scene}_${t}_$pair.json" >/dev/null ||
                log "bench $scene $t failed"
        done
    done
done
log "traversal pairs done"

# 3. The scaling tables, each traversal.
for t in $traversals; do
    in_time "scaling $t" || break
    if [ "$small" = 1 ]; then
        export SCALING_SIZES=64x64 SCALING_TRIANGLES="100 10000"
    fi
    SCALING_TRAVERSAL=$t bash "$here/scaling.sh" "$wavefront" "${label}_$t" --no-large \
        >"$results/${label}_scaling_$t.md" || log "scaling $t failed"
done
log "scaling done"

python3 - "$results" "$label" <<'PY'
import glob, json, os, statistics, sys
results, label = sys.argv[1], sys.argv[2]
print("| scene | traversal | paths/s (median of pairs) | intersect ms | shadow ms | AS MiB | AS build s |")
print("|---|---|---|---|---|---|---|")
for scene in ("cornell", "mesh", "instances"):
    for t in ("bvh", "rt"):
        runs = [json.load(open(f)) for f in
                glob.glob(os.path.join(results, "%s_traversal_%s_%s_*.json" % (label, scene, t)))]
        if not runs:
            continue
        w = [d["runs"]["wavefront"] for d in runs]
        med = lambda xs: statistics.median(xs)
        ms = lambda r, p: r["passMilliseconds"][p]["median"] if p in r.get("passMilliseconds", {}) else float("nan")
        tr = runs[0].get("traversal", {})
        print("| %s | %s | %.3f M | %.2f | %.2f | %.2f | %.3f |" % (
            scene, t, med([r["pathsPerSecond"] for r in w]) / 1e6,
            med([ms(r, "intersect") for r in w]), med([ms(r, "shadow") for r in w]),
            tr.get("accelerationBytes", 0) / 2**20, tr.get("accelerationBuildSeconds", 0.0)))
PY
if [ -n "${OUT:-}" ]; then
    tar -czf "$OUT/${label}_results.tar.gz" -C "$results" $(cd "$results" && ls "$label"_*)
    log "packed $(cd "$results" && ls "$label"_* | wc -l) files into \$OUT/${label}_results.tar.gz"
fi
log "done"
