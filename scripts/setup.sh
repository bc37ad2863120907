#!/usr/bin/env bash
# Installs whatever Debian 12 packages are missing, then configures and builds Wavefront
# (CMake, Release) into build/. Run as root on a fresh machine; safe to run again.
# Usage: [WAVEFRONT_MESA=backports|release] scripts/setup.sh [--with-tests]
set -euo pipefail
cd "$(dirname "$0")/.."
# lavapipe: Mesa 25 by default (Debian 12's backports suite; Debian 13's own), whose traversal
# code misses the cache less (docs/performance.md#mesa-250-from-bookworm-backports-2026-12-03)
# and which offers the ray-tracing extensions; WAVEFRONT_MESA=release keeps Debian 12's 22.3.
mesa=$(bash scripts/choose_mesa.sh)
packages=(
    build-essential cmake ninja-build pkg-config
    libvulkan-dev vulkan-validationlayers
    glslang-dev glslang-tools libglm-dev libtinygltf-dev libopenexr-dev libstb-dev
    libdraco-dev libmeshoptimizer-dev nlohmann-json3-dev # compressed glTF meshes
    libwebp-dev # EXT_texture_webp images
    libglfw3-dev libimgui-dev # wavefront view (WF_BUILD_VIEWER)
    python3-matplotlib # wavefront converge's charts (scripts/plot_convergence.py)
    python3-dev pybind11-dev python3-numpy # the Python module (python/, WF_BUILD_PYTHON)
)
# The backports Mesa is installed below, after the rest.
[ "$mesa" = "backports" ] || packages+=(mesa-vulkan-drivers)
tests=OFF
if [ "${1:-}" = "--with-tests" ]; then
    packages+=(googletest libgtest-dev xvfb xauth xdotool) # the viewer test: display, input
    packages+=(clang libclang-rt-14-dev) # the loader's libFuzzer and ASan+UBSan build (fuzz/)
    packages+=(gltfpack) # a meshopt-compressed scene to render (tests/gpu/test_compressed_scenes)
    packages+=(python3-pytest python3-venv) # the Python module's tests and its wheel's venv
    tests=ON
fi

missing=()
for package in "${packages[@]}"; do
    status=$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)
    [ "$status" = "install ok installed" ] || missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
    echo "setup: installing ${missing[*]}"
    sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends \
        "${missing[@]}" >/dev/null
fi

if [ "$mesa" = "backports" ]; then
    bash scripts/mesa_backports.sh
elif [ "${WAVEFRONT_MESA:-}" = "release" ]; then
    installed=$(dpkg-query -W -f='${Version}' mesa-vulkan-drivers)
    if [[ "$installed" == *bpo12* ]]; then
        echo "setup: WAVEFRONT_MESA=release: replacing Mesa $installed with Debian 12's own"
        sudo=""
        [ "$(id -u)" -eq 0 ] || sudo="sudo"
        DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends \
            --allow-downgrades mesa-vulkan-drivers/bookworm >/dev/null
    fi
fi

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DWF_BUILD_TESTS="$tests" >/dev/null
cmake --build build --parallel "$(nproc)"
