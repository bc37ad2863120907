#!/usr/bin/env bash
# Installs lavapipe (mesa-vulkan-drivers) from Debian 12's backports suite, taken from the
# machine's own Debian mirror, unless a backports Mesa is already installed. Run as root (or
# with sudo) on Debian 12; scripts/setup.sh calls it when WAVEFRONT_MESA=backports.
set -euo pipefail

installed=$(dpkg-query -W -f='${Version}' mesa-vulkan-drivers 2>/dev/null || true)
case "$installed" in *bpo12*) exit 0 ;; esac

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
list=/etc/apt/sources.list.d/wavefront-bookworm-backports.sources
if [ ! -f "$list" ]; then
    # The mirror of the stanza (deb822) or line (one-line format) that serves plain bookworm.
    mirror=""
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
    if [ -z "$mirror" ]; then
        echo "mesa_backports: no apt source for Debian 12 (bookworm) found to take the backports suite from" >&2
        exit 2
    fi
    printf 'Types: deb\nURIs: %s\nSuites: bookworm-backports\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
        "$mirror" | $sudo tee "$list" >/dev/null
fi
echo "mesa_backports: installing mesa-vulkan-drivers from bookworm-backports"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends \
    -t bookworm-backports mesa-vulkan-drivers >/dev/null
