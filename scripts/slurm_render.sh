#!/usr/bin/env bash
# Renders one image on a Slurm cluster: K parts of the samples as a job array (render
# --spp-offset), then a job that depends on them all and merges them (wavefront merge).
# Paths must be visible to every node (a shared file system); the parts and logs go to
# OUT.parts/ beside OUT.exr.
#
# Usage: scripts/slurm_render.sh SCENE.gltf OUT.exr --parts K --spp N [--wait]
#                                [--frames A..B[:STEP]] [render flags ...] [-- sbatch options ...]
#   --parts K   sample ranges, one array task each (N split as evenly as it goes; default 1
#               with --frames)
#   --frames    an animation: one array task per frame and part (frame / --fps seconds, as
#               render --frame), OUT a pattern such as out/frame_%04d.exr; one merge job
#               writes every frame
#   --wait      return when the merge job has ended, with its exit code (sbatch --wait)
#   WAVEFRONT=PATH picks the binary (default: build/wavefront beside this script's folder).
# Render flags go to every part: --guiding on guides each part with a guide it trains itself
# (each part unbiased, so the merge is too).
# Options after -- go to both sbatch calls (e.g. -- --partition=gpu --time=2:00:00).
set -euo pipefail
usage() { sed -n '2,20p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
[ $# -ge 2 ] || usage
scene=$(realpath "$1")
out=$(realpath -m "$2")
shift 2
parts="" spp="" wait=0 frames="" render=() sbatch=()
while [ $# -gt 0 ]; do
    case "$1" in
        --parts) parts=$2; shift 2 ;;
        --frames) frames=$2; shift 2 ;;
        --spp) spp=$2; shift 2 ;;
        --wait) wait=1; shift ;;
        --) shift; sbatch=("$@"); break ;;
        *) render+=("$1"); shift ;;
    esac
done
[ -n "$frames" ] && [ -z "$parts" ] && parts=1
[[ "$parts" =~ ^[1-9][0-9]*$ && "$spp" =~ ^[1-9][0-9]*$ ]] || {
    echo "slurm_render: --parts K and --spp N must be positive integers" >&2; exit 2; }
[ "$parts" -le "$spp" ] || { echo "slurm_render: more parts ($parts) than samples ($spp)" >&2; exit 2; }
wavefront=$(realpath "${WAVEFRONT:-$(dirname "$0")/../build/wavefront}")
list=(0) # the frames; one entry (unused) for a still
if [ -n "$frames" ]; then
    [[ "$frames" =~ ^([0-9]+)\.\.([0-9]+)(:([1-9][0-9]*))?$ ]] && \
        [ "${BASH_REMATCH[1]}" -le "${BASH_REMATCH[2]}" ] || {
        echo "slurm_render: --frames $frames: expected A..B or A..B:STEP" >&2; exit 2; }
    list=($(seq "${BASH_REMATCH[1]}" "${BASH_REMATCH[4]:-1}" "${BASH_REMATCH[2]}"))
    [[ "$out" == *%*d* ]] || {
        echo "slurm_render: with --frames, OUT names each frame with %d or %04d" >&2; exit 2; }
fi
dir="${out//%/}.parts"
mkdir -p "$dir"

# Part i renders samples [offset_i, offset_i + spp_i): the first spp % K parts take one more.
quoted=$(printf ' %q' "${render[@]+"${render[@]}"}")
cat >"$dir/part.sh" <<JOB
#!/usr/bin/env bash
set -euo pipefail
frames=(${list[*]})
i=\$((SLURM_ARRAY_TASK_ID % $parts))
frame=\${frames[\$((SLURM_ARRAY_TASK_ID / $parts))]}
base=$((spp / parts)) extra=$((spp % parts))
count=\$((base + (i < extra ? 1 : 0)))
offset=\$((i * base + (i < extra ? i : extra)))
timeFlags=()
[ -n "$frames" ] && timeFlags=(--frame "\$frame")
exec $(printf %q "$wavefront") render $(printf %q "$scene") -o "$dir/frame_\${frame}_part_\$i.exr" \\
    --spp "\$count" --spp-offset "\$offset" --spp-total $spp --quiet "\${timeFlags[@]}"$quoted
JOB
if [ -n "$frames" ]; then
    cat >"$dir/merge.sh" <<JOB
#!/usr/bin/env bash
set -euo pipefail
for frame in ${list[*]}; do
    $(printf %q "$wavefront") merge "$dir"/frame_\${frame}_part_*.exr -o "\$(printf $(printf %q "$out") "\$frame")"
done
JOB
else
    cat >"$dir/merge.sh" <<JOB
#!/usr/bin/env bash
exec $(printf %q "$wavefront") merge "$dir"/frame_0_part_*.exr -o $(printf %q "$out")
JOB
fi
tasks=$((parts * ${#list[@]}))
array=$(sbatch --parsable --array=0-$((tasks - 1)) --job-name=wavefront-part \
    --output="$dir/part_%a.log" "${sbatch[@]+"${sbatch[@]}"}" "$dir/part.sh")
array=${array%%;*}
waitFlag=()
[ "$wait" -eq 1 ] && waitFlag=(--wait)
echo "slurm_render: parts in job array $array ($tasks tasks), merge after them into $out"
merge=$(sbatch --parsable --dependency=afterok:"$array" --kill-on-invalid-dep=yes \
    --job-name=wavefront-merge --output="$dir/merge.log" "${waitFlag[@]+"${waitFlag[@]}"}" \
    "${sbatch[@]+"${sbatch[@]}"}" "$dir/merge.sh")
echo "slurm_render: merge job ${merge%%;*}"
