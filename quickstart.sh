#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to a rendered image: installs what is missing,
# builds, and renders scenes/cornell_box.gltf to out/cornell_box.exr and out/cornell_box.png.
set -euo pipefail
cd "$(dirname "$0")"
bash scripts/setup.sh
mkdir -p out
./build/wavefront render scenes/cornell_box.gltf -o out/cornell_box.exr "$@"
