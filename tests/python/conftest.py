"""Fixtures of the Python module's tests (ctest's python_module runs them with the build
tree's module on PYTHONPATH, WAVEFRONT_CLI the `wavefront` executable, WAVEFRONT_SCENES the
scenes folder). Images are tiny and sample counts small: the whole file runs in about a minute
on lavapipe."""
import os
import subprocess
from pathlib import Path

import pytest

import wavefront as wf

SCENES = Path(os.environ.get("WAVEFRONT_SCENES", Path(__file__).resolve().parents[2] / "scenes"))
CLI = os.environ.get("WAVEFRONT_CLI", "wavefront")
CORNELL = SCENES / "cornell_box.gltf"


@pytest.fixture(scope="session")
def renderer():
    """One renderer for the session, validation on: a test that leaves messages fails."""
    with wf.Renderer(validation=True) as r:
        yield r
        assert r.validation_messages == 0


@pytest.fixture(scope="session")
def cornell(renderer):
    return renderer.load(CORNELL)


def run_cli(*args, check=True):
    """`wavefront ARGS...`: the completed process (stdout, stderr as text)."""
    result = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)
    if check and result.returncode != 0:
        raise AssertionError(f"wavefront {' '.join(map(str, args))} exited "
                             f"{result.returncode}: {result.stderr}")
    return result


def cli_render(tmp_path, name, *flags):
    """Renders the Cornell box with the CLI and returns its EXR image."""
    out = tmp_path / f"{name}.exr"
    run_cli("render", CORNELL, "-o", out, "--quiet", *flags)
    return wf.read_exr(out)[0]
