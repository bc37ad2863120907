#!/usr/bin/env bash
# The Slurm farm end to end on this machine: installs slurm-wlm and munge if missing (root),
# starts munged, slurmctld and slurmd on localhost with a generated one-node configuration,
# renders the Cornell box as 4 parts with scripts/slurm_render.sh, and checks that the merged
# image equals a single-machine render, and a 4-frame sequence (--frames, 2 parts a frame)
# against render --frames; then stops the daemons it started, by their pids.
# Usage: test_slurm.sh PATH/TO/wavefront PATH/TO/wf_compare_images PROJECT_ROOT
set -u
wavefront=$(realpath "$1")
compare=$(realpath "$2")
root=$(realpath "$3")
work=$(mktemp -d)
started=()
cleanup() {
    for pidfile in "${started[@]+"${started[@]}"}"; do
        [ -s "$pidfile" ] && kill "$(cat "$pidfile")" 2>/dev/null
    done
    sleep 1
    rm -rf "$work"
}
trap cleanup EXIT
fail() { echo "FAIL $*"; echo "0 passed, 1 failed"; exit 1; }

if ! command -v slurmctld >/dev/null || ! command -v munged >/dev/null; then
    [ "$(id -u)" -eq 0 ] || fail "slurm-wlm and munge are missing and this is not root"
    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
        --no-install-recommends slurm-wlm munge >/dev/null || fail "apt-get install slurm-wlm munge"
fi

# The daemons below are the machine's (munge's socket, slurm's ports): one run of this test at a
# time on a machine, whatever else runs (two checkouts' suites at once wait here in turn).
exec 9>/tmp/wavefront-slurm-test.lock
flock 9

# munge: a key if there is none, and the daemon as the munge user unless one is running.
if [ ! -S /run/munge/munge.socket.2 ]; then
    if [ ! -s /etc/munge/munge.key ]; then
        dd if=/dev/urandom of=/etc/munge/munge.key bs=1024 count=1 status=none
        chown munge:munge /etc/munge/munge.key && chmod 400 /etc/munge/munge.key
    fi
    mkdir -p /run/munge && chown munge:munge /run/munge
    runuser -u munge -- /usr/sbin/munged --pid-file=/run/munge/wavefront-test.pid ||
        fail "munged did not start"
    started+=(/run/munge/wavefront-test.pid)
fi

host=$(hostname -s)
mkdir -p "$work/state" "$work/spool"
cat >"$work/slurm.conf" <<CONF
ClusterName=wavefront-test
SlurmctldHost=$host
SlurmUser=root
AuthType=auth/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
SlurmctldPort=16817
SlurmdPort=16818
NodeName=$host CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$work/slurm.conf"
started+=("$work/slurmctld.pid" "$work/slurmd.pid")
slurmctld -f "$SLURM_CONF" || fail "slurmctld did not start"
slurmd -f "$SLURM_CONF" || fail "slurmd did not start"
# Generous waits and limits below: only a hang reaches them, not a busy machine.
for _ in $(seq 1 600); do
    sinfo -h -o %T 2>/dev/null | grep -qE "idle|mixed" && break
    sleep 1
done
sinfo -h -o %T | grep -qE "idle|mixed" || { tail -5 "$work/slurmctld.log"; fail "no idle node"; }

flags=(--width 40 --max-depth 4)
WAVEFRONT="$wavefront" timeout 3600 bash "$root/scripts/slurm_render.sh" \
    "$root/scenes/cornell_box.gltf" "$work/farm.exr" --parts 4 --spp 18 --wait "${flags[@]}" \
    -- --time=60 || { cat "$work"/farm.exr.parts/*.log; fail "slurm_render.sh"; }
[ -s "$work/farm.exr" ] || fail "no merged image"
"$wavefront" render "$root/scenes/cornell_box.gltf" -o "$work/one.exr" --spp 18 --quiet \
    "${flags[@]}" || fail "single-machine render"
"$compare" "$work/farm.exr" "$work/one.exr" --spp 18 --tolerance 1e-5 ||
    fail "the farm's image differs from one machine's"
echo "4 parts on Slurm merged into one run's image"

# A 4-frame sequence of the animated scene, each frame in 2 parts: every merged frame equals
# that frame of one machine's render --frames.
flags=(--width 32 --max-depth 3)
WAVEFRONT="$wavefront" timeout 3600 bash "$root/scripts/slurm_render.sh" \
    "$root/scenes/animated_arm.gltf" "$work/anim/frame_%04d.exr" --frames 0..18:6 --parts 2 \
    --spp 6 --wait "${flags[@]}" -- --time=60 ||
    { cat "$work"/anim/*.parts/*.log; fail "slurm_render.sh --frames"; }
"$wavefront" render "$root/scenes/animated_arm.gltf" -o "$work/seq_%d.exr" --frames 0..18:6 \
    --spp 6 --quiet "${flags[@]}" || fail "single-machine --frames"
for f in 0 6 12 18; do
    "$compare" "$work/anim/frame_$(printf %04d $f).exr" "$work/seq_$f.exr" --spp 6 \
        --tolerance 1e-5 || fail "frame $f of the farm differs from one machine's"
done
echo "a 4-frame sequence on Slurm (8 tasks) equals one machine's render --frames"
echo "2 passed, 0 failed"
