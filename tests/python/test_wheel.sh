#!/usr/bin/env bash
# `pip install .` in CI time: the wheel is made by scikit-build-core from the ctest build tree
# itself (its cache's own options passed back, so nothing recompiles), installed into a fresh
# venv, and both examples run from it in an empty folder, far from the source and build trees.
# Skipped (exit 77) when PyPI, where pip fetches scikit-build-core, cannot be reached.
# Usage: test_wheel.sh SOURCE_DIR BUILD_DIR PYTHON
set -euo pipefail
src=$1
build=$2
python=$3
work=$(mktemp -d)
cache_value() { sed -n "s/^$1:[A-Z]*=//p" "$build/CMakeCache.txt"; }
tests=$(cache_value WF_BUILD_TESTS)
viewer=$(cache_value WF_BUILD_VIEWER)
python_exe=$(cache_value WF_PYTHON_EXECUTABLE) # the Python the module was built for
restore() {
    # scikit-build-core configured the tree with its own variables: put the cache back.
    cmake -S "$src" -B "$build" -U "SKBUILD*" -DCMAKE_INSTALL_PREFIX=/usr/local \
        -DPython3_EXECUTABLE="$python_exe" >/dev/null || true
    rm -rf "$work"
}
trap restore EXIT

"$python" -m venv --system-site-packages "$work/venv"
pip=("$work/venv/bin/python" -m pip --disable-pip-version-check -q)
if ! "${pip[@]}" download --no-deps -d "$work/backend" "scikit-build-core>=0.10" >/dev/null 2>&1
then
    echo "python_wheel: skipped: PyPI is out of reach (pip fetches scikit-build-core there)"
    trap - EXIT
    rm -rf "$work"
    exit 77
fi
"${pip[@]}" wheel --no-deps -w "$work/wheels" "$src" --config-settings=build-dir="$build" \
    --config-settings=cmake.define.WF_BUILD_TESTS="$tests" \
    --config-settings=cmake.define.WF_BUILD_VIEWER="$viewer" \
    --config-settings=cmake.define.Python3_EXECUTABLE="$python_exe"
wheel=$(ls "$work"/wheels/wavefront-*.whl)
echo "python_wheel: built $(basename "$wheel")"
"${pip[@]}" install --no-deps --no-index "$wheel"

mkdir "$work/run"
cd "$work/run"
unset PYTHONPATH WAVEFRONT_SHADER_DIR
venv_python="$work/venv/bin/python"
"$venv_python" - "$work/venv" <<'PY'
import sys
import wavefront as wf
from wavefront import _wavefront
assert wf.__file__.startswith(sys.argv[1]), wf.__file__
assert _wavefront.shader_dir().startswith(sys.argv[1]), _wavefront.shader_dir()
print("python_wheel: imported from", wf.__file__, "shaders", _wavefront.shader_dir())
PY
"$venv_python" "$src/examples/compare_samplers.py" "$src/scenes/cornell_box.gltf" chart.png \
    --time 0.05
"$venv_python" "$src/examples/aov_side_by_side.py" "$src/scenes/cornell_box.gltf" aovs.png
test -s chart.png && test -s aovs.png
echo "python_wheel: both examples ran from the installed wheel"
