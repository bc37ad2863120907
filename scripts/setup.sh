#!/usr/bin/env bash
# Installs whatever Debian 12 packages are missing, then configures and builds Wavefront
# (CMake, Release) into build/. Run as root on a fresh machine; safe to run again.
# Usage: [WAVEFRONT_MESA=backports] scripts/setup.sh [--with-tests]
set -euo pipefail
cd "$(dirname "$0")/.."
case "${WAVEFRONT_MESA:-}" in
"" | backports) ;;
*) echo "setup: WAVEFRONT_MESA must be 'backports' or unset, not '${WAVEFRONT_MESA}'" >&2; exit 2 ;;
esac

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
# lavapipe: the release's Mesa 22.3, or with WAVEFRONT_MESA=backports Debian 12's backports
# suite's Mesa 25.0 (installed below, after the rest), whose traversal code misses the cache
# less: 1.44x on a 300k-triangle mesh (docs/performance.md#mesa-250-from-bookworm-backports-2026-12-03).
[ "${WAVEFRONT_MESA:-}" = "backports" ] || packages+=(mesa-vulkan-drivers)
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

[ "${WAVEFRONT_MESA:-}" != "backports" ] || bash scripts/mesa_backports.sh

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DWF_BUILD_TESTS="$tests" >/dev/null
cmake --build build --parallel "$(nproc)"
