"""Errors: the CLI's refusals as ValueError with the same words (keywords for flags), bad
scenes as SceneError with the CLI's line, DeviceError, a closed renderer's refusals."""
import os
import subprocess
import sys

import pytest

import wavefront as wf
from conftest import CLI, CORNELL, run_cli
from wavefront._options import keyword_message

# Option sets the CLI refuses, as render() keywords and as the same flags.
REFUSALS = [
    dict(max_depth=0),
    dict(spp=0),
    dict(seed=-1),
    dict(sampler="nope"),
    dict(light_sampling="sometimes"),
    dict(width=20000),
    dict(clamp=-1.0),
    dict(aov="albedo,bogus"),
    dict(aov="albedo,albedo"),
    dict(spp=4, spp_total=2),
    dict(target_error=0.1, spp=4),
    dict(target_error=0.1, sampler="stratified"),
    dict(time_limit=1.0, sampler="multijitter"),
    dict(no_randomize=True, sampler="independent"),
]


def cli_flags(options):
    flags = []
    for key, value in options.items():
        flags.append("--" + key.replace("_", "-"))
        if value is not True:
            flags.append(str(value))
    return flags


@pytest.mark.parametrize("options", REFUSALS, ids=lambda o: ",".join(o))
def test_every_cli_refusal_has_its_python_twin(renderer, cornell, tmp_path, options):
    with pytest.raises(ValueError) as raised:
        renderer.render(cornell, **options)
    cli = run_cli("render", CORNELL, "-o", tmp_path / "x.exr", *cli_flags(options), check=False)
    assert cli.returncode == 2
    line = cli.stderr.strip().splitlines()[-1]
    assert line.startswith("wavefront: ")
    assert str(raised.value) == keyword_message(line[len("wavefront: "):])
    assert "\n" not in str(raised.value)


def test_bad_values_of_python_types(renderer, cornell):
    with pytest.raises(ValueError, match="no_randomize is True or False"):
        renderer.render(cornell, no_randomize="yes")
    with pytest.raises(ValueError, match="spp takes a number"):
        renderer.render(cornell, spp=True)
    with pytest.raises(TypeError):
        renderer.render(cornell, samples=4)
    with pytest.raises(TypeError, match="wavefront.Scene"):
        renderer.render(str(CORNELL))
    with pytest.raises(ValueError, match="instancing"):
        renderer.load(CORNELL, instancing="sometimes")


@pytest.mark.parametrize("name", ["missing.gltf", "not_gltf.gltf"])
def test_bad_scene_raises_scene_error_with_the_cli_message(renderer, tmp_path, name):
    path = tmp_path / name
    if name == "not_gltf.gltf":
        path.write_text("{ this is not json")
    with pytest.raises(wf.SceneError) as raised:
        renderer.load(path)
    cli = run_cli("render", path, "-o", tmp_path / "x.exr", check=False)
    assert cli.returncode == 2
    assert cli.stderr.strip().splitlines()[-1] == "wavefront: " + str(raised.value)


def test_unknown_camera_is_a_scene_error(renderer):
    with pytest.raises(wf.SceneError, match="camera"):
        renderer.load(CORNELL, camera="no such camera")


def test_no_device_raises_device_error():
    with pytest.raises(wf.DeviceError, match="out of range"):
        wf.Renderer(device=99)
    # No driver at all: a fresh interpreter whose Vulkan loader finds no ICD.
    code = ("import wavefront as wf\n"
            "try:\n    wf.Renderer()\nexcept wf.DeviceError as e:\n    print('DeviceError:', e)\n")
    env = dict(os.environ, VK_ICD_FILENAMES="/nonexistent.json", VK_DRIVER_FILES="/nonexistent.json")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env)
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("DeviceError: No Vulkan"), result.stdout
    assert "mesa-vulkan-drivers" in result.stdout


def test_closed_renderer_refuses_and_close_is_idempotent():
    r = wf.Renderer()
    scene = r.load(CORNELL)
    r.close()
    r.close()
    assert r.closed
    for call in (lambda: r.render(scene, width=8, spp=1), lambda: r.load(CORNELL),
                 lambda: r.device_name, lambda: list(r.render_progressive(scene, spp=1)),
                 lambda: r.converge(scene, reference=1, methods=["sobol"], seeds=[1])):
        with pytest.raises(wf.ClosedError, match="closed"):
            call()
    with wf.Renderer() as other:  # the scene outlives its renderer: host data
        assert other.render(scene, width=8, spp=1, max_depth=2).spp == 1
    assert other.closed


def test_image_files(tmp_path):
    import numpy as np
    image = np.random.default_rng(1).random((5, 7, 3), dtype=np.float32)
    wf.write_exr(tmp_path / "a.exr", image, {"note": "hi", "spp": 3, "gain": 0.5})
    back, header = wf.read_exr(tmp_path / "a.exr")
    assert np.array_equal(back, image)
    assert header["note"] == "hi" and header["spp"] == 3 and header["gain"] == 0.5
    wf.write_png(tmp_path / "a.png", image)
    assert (tmp_path / "a.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    with pytest.raises(ValueError, match="shape"):
        wf.write_exr(tmp_path / "b.exr", image[..., :2])
    with pytest.raises(wf.ImageError, match="missing.exr"):
        wf.read_exr(tmp_path / "missing.exr")
    with pytest.raises(wf.ImageError, match="does not exist"):
        wf.write_png(tmp_path / "no" / "a.png", image)
    with pytest.raises(ValueError, match="differ in shape"):
        wf.relmse(image, image[:4])
    assert wf.relmse(image, image) == 0.0


def test_devices_lists_this_device(renderer):
    devices = wf.devices()
    assert any(d["name"] == renderer.device_name for d in devices)
    assert all(d["subgroup_size"] >= 1 and d["driver"] and d["type"] for d in devices)
