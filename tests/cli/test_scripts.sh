#!/usr/bin/env bash
# The project's helper scripts: scripts/setup.sh's WAVEFRONT_MESA choice and
# bench/peer_summary.py on the committed peer results.
# Usage: test_scripts.sh PROJECT_ROOT
root=$1
source "$(dirname "$0")/harness.sh"

check "setup refuses an unknown WAVEFRONT_MESA" 2 env WAVEFRONT_MESA=newest bash "$root/scripts/setup.sh"
expect "setup's error is one line naming the variable" \
    bash -c "[ \$(wc -l <'$work/stderr') -eq 1 ] && grep -q 'WAVEFRONT_MESA' '$work/stderr'"
check "WAVEFRONT_MESA=release keeps the release's Mesa" 0 env WAVEFRONT_MESA=release bash "$root/scripts/choose_mesa.sh"
expect "and says so" grep -qx release "$work/stdout"

# The fallback: a backports suite that cannot be reached never fails the set-up. The probe
# runs apt in a scratch folder, so the machine's package lists stay as they are.
codename=$( (. /etc/os-release && echo "${VERSION_CODENAME:-}") || true)
if [ "$codename" = "bookworm" ]; then
    check "the backports suite's probe fails on a missing suite" 1 \
        env WAVEFRONT_BACKPORTS_SUITE=bookworm-no-such-suite bash "$root/scripts/mesa_backports.sh" --check
    check "set-up's choice falls back when the suite is missing" 0 \
        env WAVEFRONT_BACKPORTS_SUITE=bookworm-no-such-suite bash "$root/scripts/choose_mesa.sh"
    installed=$(dpkg-query -W -f='${Version}' mesa-vulkan-drivers 2>/dev/null || true)
    if [[ "$installed" == *bpo12* ]]; then
        expect "keeping the backports Mesa already installed" grep -qx backports "$work/stdout"
        expect "with one warning naming the suite" bash -c "[ \$(wc -l <'$work/stderr') -eq 1 ] &&
            grep -q 'warning: bookworm-no-such-suite cannot be reached; keeping' '$work/stderr'"
    else
        expect "installing the release's Mesa" grep -qx release "$work/stdout"
        expect "with one warning naming the suite" bash -c "[ \$(wc -l <'$work/stderr') -eq 1 ] &&
            grep -q 'warning: bookworm-no-such-suite cannot be reached; installing' '$work/stderr'"
    fi
    # The real suite, reachable wherever the set-up itself could install packages.
    check "the backports suite's probe finds mesa-vulkan-drivers" 0 bash "$root/scripts/mesa_backports.sh" --check
fi

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
