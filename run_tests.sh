#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to the whole test suite: installs what is
# missing, builds with tests, and runs them (CPU tests, then GPU tests on the Vulkan device
# present, lavapipe in CI, with the Khronos validation layer on). The default lavapipe is Mesa 25;
# with no arguments a smoke subset then runs on Debian 12's own Mesa 22.3 as well, unpacked
# beside it (scripts/mesa_release_copy.sh), so the older driver keeps working.
set -euo pipefail
cd "$(dirname "$0")"
bash scripts/setup.sh --with-tests
# The glTF loader alone under ASan+UBSan (its unit tests and a 30 s libFuzzer run from
# tests/gltf_corpus): a small clang build beside the main one (fuzz/CMakeLists.txt).
cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
    -DCMAKE_CXX_COMPILER=clang++ -DWF_FUZZ=ON >/dev/null
cmake --build build-fuzz --parallel "$(nproc)"
status=0
(cd build && ctest --output-on-failure --parallel 2 "$@") || status=1
(cd build-fuzz && ctest --output-on-failure) || status=1

smoke='^(Cornell\.|FurnaceDepth\.|Albedos/Furnace\.|Instancing\.|Textures\.|ShadeSplit\.|Shaders\.|Estimators\.FurnaceForEveryEstimator|cli_end_to_end)'
if [ $# -eq 0 ] && icd=$(bash scripts/mesa_release_copy.sh build/mesa-release); then
    driver=$(VK_ICD_FILENAMES=$icd ./build/wavefront render scenes/cornell_box.gltf --width 8 \
        --height 8 --spp 1 --verbose -o build/mesa-release/check.exr 2>&1 | head -n 1 || true)
    echo "run_tests: smoke subset on $driver"
    if [[ "$driver" == *"Mesa 22.3"* ]]; then
        (cd build && VK_ICD_FILENAMES=$icd ctest --output-on-failure --parallel 2 -R "$smoke") ||
            status=1
    else
        echo "run_tests: the unpacked Mesa 22.3 ($icd) is not the driver that ran" >&2
        status=1
    fi
elif [ $# -eq 0 ]; then
    echo "run_tests: warning: no smoke subset on Mesa 22.3 (the line above says why)" >&2
fi
exit $status
