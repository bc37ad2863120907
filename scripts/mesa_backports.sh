#!/usr/bin/env bash
# lavapipe (mesa-vulkan-drivers) from Debian 12's backports suite, taken from the machine's own
# Debian mirror. scripts/setup.sh runs it through scripts/choose_mesa.sh.
# Usage: mesa_backports.sh           install it, unless a backports Mesa is installed already
#        mesa_backports.sh --check   exit 0 when the suite is reachable and carries
#                                    mesa-vulkan-drivers; nothing on the machine changes
# WAVEFRONT_BACKPORTS_SUITE names another suite (default bookworm-backports): the tests point
# it at a missing one to see the set-up fall back.
set -euo pipefail
suite=${WAVEFRONT_BACKPORTS_SUITE:-bookworm-backports}

# The mirror of the stanza (deb822) or line (one-line format) that serves plain bookworm.
bookworm_mirror() {
    local mirror=""
    if [ -f /etc/apt/sources.list.d/debian.sources ]; then
        mirror=$(awk 'BEGIN { RS = "" }
            /(^|\n)Suites:[^\n]*[ \t]bookworm([ \t]|\n|$)/ {
                if (match($0, /(^|\n)URIs:[ \t]*[^ \t\n]+/)) {
                    uri = substr($0, RSTART, RLENGTH); sub(/^\n?URIs:[ \t]*/, "", uri)
                    print uri; exit
                }
            }' /etc/apt/sources.list.d/debian.sources)
    fi
    if [ -z "$mirror" ] && [ -f /etc/apt/sources.list ]; then
        mirror=$(awk '$1 == "deb" && $3 == "bookworm" { print $2; exit }' /etc/apt/sources.list)
    fi
    echo "$mirror"
}

mirror=$(bookworm_mirror)
if [ -z "$mirror" ]; then
    echo "mesa_backports: no apt source for Debian 12 (bookworm) found to take $suite from" >&2
    exit 2
fi

if [ "${1:-}" = "--check" ]; then
    # apt-get update into a scratch folder of its own: the machine's package lists stay as
    # they are, and a missing suite fails here instead of in the install.
    scratch=$(mktemp -d)
    trap 'rm -rf "$scratch"' EXIT
    mkdir -p "$scratch/lists/partial" "$scratch/parts"
    echo "deb [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] $mirror $suite main" \
        >"$scratch/sources.list"
    apt-get update -qq -o Dir::Etc::SourceList="$scratch/sources.list" \
        -o Dir::Etc::SourceParts="$scratch/parts" -o Dir::State::Lists="$scratch/lists" \
        -o APT::Sandbox::User=root -o Acquire::Retries=1 -o Acquire::http::Timeout=20 \
        >/dev/null 2>&1 || exit 1
    # apt keeps the lists compressed (lz4 here); its helper reads them whatever the format.
    for packages in "$scratch"/lists/*_Packages*; do
        /usr/lib/apt/apt-helper cat-file "$packages" 2>/dev/null |
            grep '^Package: mesa-vulkan-drivers$' >/dev/null && exit 0
    done
    exit 1
fi

installed=$(dpkg-query -W -f='${Version}' mesa-vulkan-drivers 2>/dev/null || true)
case "$installed" in *bpo12*) exit 0 ;; esac

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
list=/etc/apt/sources.list.d/wavefront-bookworm-backports.sources
if [ ! -f "$list" ]; then
    printf 'Types: deb\nURIs: %s\nSuites: %s\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
        "$mirror" "$suite" | $sudo tee "$list" >/dev/null
fi
echo "mesa_backports: installing mesa-vulkan-drivers from $suite"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends \
    -t "$suite" mesa-vulkan-drivers >/dev/null
