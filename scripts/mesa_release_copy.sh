#!/usr/bin/env bash
# Unpacks Debian 12's own lavapipe (Mesa 22.3) into a folder beside the installed backports
# Mesa, so that run_tests.sh can run a smoke subset on the older driver too. Prints the path of
# the ICD file to put in VK_ICD_FILENAMES; exits 1 with one line on stderr when there is
# nothing to unpack (the release's Mesa is the installed one) or it cannot be downloaded.
# Usage: mesa_release_copy.sh FOLDER
set -euo pipefail
folder=$(realpath -m "$1")
installed=$(dpkg-query -W -f='${Version}' mesa-vulkan-drivers 2>/dev/null || true)
if [[ "$installed" != *bpo12* ]]; then
    echo "mesa_release_copy: the installed Mesa ${installed:-(none)} is the release's own" >&2
    exit 1
fi
version=$(apt-cache madison mesa-vulkan-drivers | awk -F' *[|] *' '$2 !~ /bpo/ { print $2; exit }')
if [ -z "$version" ]; then
    echo "mesa_release_copy: apt knows no release version of mesa-vulkan-drivers" >&2
    exit 1
fi
icd="$folder/lvp_icd_$version.json"
if [ ! -f "$icd" ]; then
    rm -rf "$folder" && mkdir -p "$folder/debs"
    if ! (cd "$folder/debs" && apt-get download -qq "mesa-vulkan-drivers=$version" >/dev/null 2>&1); then
        echo "mesa_release_copy: cannot download mesa-vulkan-drivers $version" >&2
        exit 1
    fi
    dpkg-deb -x "$folder"/debs/mesa-vulkan-drivers_*.deb "$folder/root"
    library=$(find "$folder/root" -name libvulkan_lvp.so | head -n 1)
    printf '{ "file_format_version": "1.0.0",\n  "ICD": { "library_path": "%s", "api_version": "1.3.230" } }\n' \
        "$library" >"$icd"
fi
echo "$icd"
