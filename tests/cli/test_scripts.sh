#!/usr/bin/env bash
# The project's helper scripts: scripts/setup.sh's WAVEFRONT_MESA choice and
# bench/peer_summary.py on the committed peer results.
# Usage: test_scripts.sh PROJECT_ROOT
root=$1
source "$(dirname "$0")/harness.sh"

check "setup refuses an unknown WAVEFRONT_MESA" 2 env WAVEFRONT_MESA=newest bash "$root/scripts/setup.sh"
expect "setup's error is one line naming the variable" \
    bash -c "[ \$(wc -l <'$work/stderr') -eq 1 ] && grep -q 'WAVEFRONT_MESA' '$work/stderr'"

results="$root/bench/results"
check "peer summary, Mesa 22.3" 0 python3 "$root/bench/peer_summary.py" "$results"/lavapipe_peer_llvm_*.json
expect "peer summary names the driver" grep -q "Vulkan driver: llvmpipe Mesa 22.3" "$work/stdout"
expect "peer summary has six scenes and their mean" grep -q "geometric mean (6 scenes)" "$work/stdout"
check "peer summary, Mesa 25.0" 0 python3 "$root/bench/peer_summary.py" "$results"/lavapipe_mesa25_peer_llvm_*.json
expect "peer summary names Mesa 25" grep -q "Vulkan driver: llvmpipe Mesa 25.0" "$work/stdout"
check "peer summary refuses two drivers in one table" 1 python3 "$root/bench/peer_summary.py" \
    "$results/lavapipe_peer_llvm_mesh.json" "$results/lavapipe_mesa25_peer_llvm_mesh.json"
expect "and says why" grep -q "mix Vulkan drivers" "$work/stderr"

finish
