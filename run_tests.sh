#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to the whole test suite: installs what is
# missing, builds with tests, and runs them (CPU tests, then GPU tests on the Vulkan device
# present, lavapipe in CI, with the Khronos validation layer on).
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
exit $status
