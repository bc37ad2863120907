#!/usr/bin/env bash
# The scaling tables of the README: paths/s against resolution (the Cornell box, 256^2 to
# 1920x1080), against scene size (bench/make_scaling_scene.py, 10^2 to 10^6 triangles, four
# materials, wavefront and megakernel in one run), and production sizes (10^7 unique
# triangles; 10^6 and 5 x 10^6 unique beside 10^9 instanced), one `wavefront bench` per row.
# Raw JSON goes to bench/results/<label>_*.json; the tables go to stdout as Markdown.
#
#   bash bench/scaling.sh [path/to/wavefront] [label] [--no-large]   (label default: lavapipe)
#
# SCALING_TRAVERSAL=bvh|rt|auto passes --traversal (default: none, i.e. auto), and
# SCALING_SIZES / SCALING_TRIANGLES replace the lists of resolutions and scene sizes (the dry
# run of bench/gpu_run.sh takes small ones).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
wavefront=${1:-$root/build/wavefront}
label=${2:-lavapipe}
large=1
[ "${3:-}" = "--no-large" ] && large=0
results=$here/results
scenes=$(mktemp -d)
trap 'rm -rf "$scenes"' EXIT
mkdir -p "$results"
common=(--max-depth 8 --warmup 1 -q)
[ -n "${SCALING_TRAVERSAL:-}" ] && common+=(--traversal "$SCALING_TRAVERSAL")

for size in ${SCALING_SIZES:-256x256 512x512 1024x1024 1920x1080}; do
    w=${size%x*}; h=${size#*x}
    frames=$(( w * h > 600000 ? 3 : 6 ))
    "$wavefront" bench "$root/scenes/cornell_box.gltf" --width "$w" --height "$h" \
        --frames "$frames" "${common[@]}" --json "$results/${label}_resolution_${size}.json" \
        > /dev/null
done
for tris in ${SCALING_TRIANGLES:-100 1000 10000 100000 1000000}; do
    python3 "$here/make_scaling_scene.py" "$scenes/scene_$tris.gltf" --triangles "$tris" > /dev/null
    "$wavefront" bench "$scenes/scene_$tris.gltf" --width 256 --frames 4 "${common[@]}" \
        --compare-megakernel --json "$results/${label}_scene_${tris}.json" > /dev/null
done

if [ "$large" = 1 ]; then
    # unique triangles, instanced triangles: each scene written, benched and deleted in turn
    for spec in 10000000:0 1000000:1000000000 5000000:1000000000; do
        unique=${spec%:*}; instanced=${spec#*:}
        file=$scenes/large_${unique}_${instanced}.gltf
        python3 "$here/make_scaling_scene.py" "$file" --triangles "$unique" --unique \
            --instanced-triangles "$instanced" > /dev/null
        "$wavefront" bench "$file" --width 256 --frames 2 "${common[@]}" \
            --json "$results/${label}_large_${unique}_${instanced}.json" > /dev/null
        rm -f "$file"
    done
fi

python3 - "$results" "$label" <<'PY'
import glob, json, os, sys
results, label = sys.argv[1], sys.argv[2]
def load(pattern):
    runs = [json.load(open(f)) for f in glob.glob(os.path.join(results, pattern))]
    return sorted(runs, key=lambda d: (d["triangles"], d["width"] * d["height"]))
rows = load(label + "_resolution_*.json")
print("| resolution | paths/frame | wavefront paths/s | frame ms (median) | longest submit ms |")
print("|---|---|---|---|---|")
for d in rows:
    r = d["runs"]["wavefront"]
    print("| %dx%d | %d | %.3f M | %.0f | %.0f |" % (
        d["width"], d["height"], d["width"] * d["height"] * d["sppPerFrame"],
        r["pathsPerSecond"] / 1e6, r["frameMilliseconds"]["median"],
        r["longestSubmitSeconds"] * 1e3))
print()
print("| triangles | traversal | traversal cost | BVH SAH cost | build ms | wavefront paths/s | "
      "megakernel paths/s | wavefront / megakernel | rays/s (wavefront) |")
print("|---|---|---|---|---|---|---|---|---|")
for d in load(label + "_scene_*.json"):
    w, m = d["runs"]["wavefront"], d["runs"]["megakernel"]
    print("| %d | %s | %g | %.1f | %.0f | %.3f M | %.3f M | %.2f | %.2f M |" % (
        d["triangles"], d.get("traversal", {}).get("mode", "bvh"),
        d["bvh"].get("traversalCost", 1.0), d["bvh"]["sahCost"],
        d["bvh"]["buildSeconds"] * 1e3,
        w["pathsPerSecond"] / 1e6, m["pathsPerSecond"] / 1e6, d["wavefrontOverMegakernel"],
        w["raysPerSecond"]["total"] / 1e6))
large = load(label + "_large_*.json")
if large:
    print()
    print("| unique triangles | as placed | instances | load s | build s | build M triangles/s | "
          "paths/s | GPU MiB | peak host MiB | host bytes per unique triangle |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for d in large:
        w = d["runs"]["wavefront"]
        host = d.get("peakHostMemoryBytes", 0)
        print("| %d | %d | %d | %s | %.2f | %.2f | %.3f M | %.0f | %.0f | %.0f |" % (
            d["triangles"], d.get("instancedTriangles", d["triangles"]), d.get("instances", 0),
            "%.2f" % d["loadSeconds"] if "loadSeconds" in d else "-", d["bvh"]["buildSeconds"], d["triangles"] / d["bvh"]["buildSeconds"] / 1e6,
            w["pathsPerSecond"] / 1e6, w["memoryTotalBytes"] / 2**20, host / 2**20,
            host / d["triangles"]))
print()
print("device: %s" % rows[0]["device"] if rows else "")
PY
