#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to the whole test suite: installs what is
# missing, builds with tests, and runs them (CPU tests, then GPU tests on the Vulkan device
# present, lavapipe in CI, with the Khronos validation layer on).
set -euo pipefail
cd "$(dirname "$0")"
bash scripts/setup.sh --with-tests
cd build
ctest --output-on-failure --parallel 2 "$@"
