#!/usr/bin/env bash
# Which lavapipe scripts/setup.sh installs; prints one word on stdout:
#   backports  Debian 12's backports suite's Mesa 25 (the default on Debian 12)
#   release    the release's own Mesa (22.3 on Debian 12; Debian 13's is already 25)
# WAVEFRONT_MESA=backports|release chooses; unset means the newest Mesa the release can reach.
# Where the backports suite cannot be reached it falls back to the release's Mesa, or keeps a
# backports Mesa already installed, with one warning line: a set-up never fails for it.
set -euo pipefail
here=$(dirname "$0")
case "${WAVEFRONT_MESA:-}" in
"" | backports | release) ;;
*) echo "setup: WAVEFRONT_MESA must be 'backports', 'release' or unset, not '${WAVEFRONT_MESA}'" >&2; exit 2 ;;
esac
[ "${WAVEFRONT_MESA:-}" != "release" ] || { echo release; exit 0; }

codename=$( (. /etc/os-release 2>/dev/null && echo "${VERSION_CODENAME:-}") || true)
if [ "$codename" != "bookworm" ]; then
    # Debian 13 and later ship Mesa 25 or newer themselves.
    [ -z "${WAVEFRONT_MESA:-}" ] ||
        echo "setup: warning: the backports Mesa is Debian 12's; using this system's own Mesa" >&2
    echo release
    exit 0
fi

suite=${WAVEFRONT_BACKPORTS_SUITE:-bookworm-backports}
installed=$(dpkg-query -W -f='${Version}' mesa-vulkan-drivers 2>/dev/null || true)
if bash "$here/mesa_backports.sh" --check; then
    echo backports
elif [[ "$installed" == *bpo12* ]]; then
    echo "setup: warning: $suite cannot be reached; keeping the installed Mesa $installed" >&2
    echo backports
else
    echo "setup: warning: $suite cannot be reached; installing Debian 12's own Mesa 22.3 instead" >&2
    echo release
fi
