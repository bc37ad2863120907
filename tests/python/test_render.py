"""Renders: arrays as promised, the CLI's image bit for bit, seeds, the 1/spp rate,
progressive passes."""
import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import wavefront as wf
from conftest import CORNELL, cli_render, run_cli


def test_output_is_a_real_float32_array(renderer, cornell):
    out = renderer.render(cornell, width=24, spp=2, max_depth=3, aov=("albedo", "normal",
                                                                     "depth", "samples"))
    image = out.image
    assert isinstance(image, np.ndarray)
    assert image.dtype == np.float32 and image.ndim == 3 and image.shape[2] == 3
    assert image.shape[1] == 24 and out.width == 24 and out.height == image.shape[0]
    assert image.flags.c_contiguous and image.flags.writeable and image.flags.owndata is False
    assert np.isfinite(image).all() and image.mean() > 0
    assert out.aov["albedo"].shape == image.shape and out.aov["normal"].shape == image.shape
    assert out.aov["depth"].shape == image.shape[:2]
    assert (out.aov["samples"] == 2).all()
    assert out.spp == 2 and out.seconds > 0
    assert out.stats["spp"] == 2 and out.stats["width"] == 24 and out.stats["paths"] > 0
    assert out.stats["triangles"] == cornell.info["triangles"] > 0
    json.dumps(out.stats)  # plain data


def test_scene_info(cornell):
    info = cornell.info
    assert info["triangles"] > 0 and info["materials"] > 0 and info["lights"]["emitters"] > 0
    assert info["kinds"] and set(info["kinds"]) <= {"diffuse", "specular", "general"}
    low, high = info["bounds"]
    assert all(h > l for l, h in zip(low, high))


@pytest.mark.parametrize("seed", [3, 11])
def test_same_image_as_the_cli_bit_for_bit(renderer, cornell, tmp_path, seed):
    # The second seed reuses the first render's renderer (restart), which must not show.
    flags = dict(width=40, spp=3, max_depth=4, sampler="halton", light_sampling="mis")
    out = renderer.render(cornell, seed=seed, **flags)
    cli = cli_render(tmp_path, "cli", "--width", 40, "--spp", 3, "--max-depth", 4,
                     "--sampler", "halton", "--light-sampling", "mis", "--seed", seed)
    assert cli.shape == out.image.shape
    assert np.array_equal(cli.view(np.uint32), out.image.view(np.uint32))


def test_aov_matches_the_cli_layers(renderer, cornell, tmp_path):
    out = renderer.render(cornell, width=20, spp=2, max_depth=3, aov="albedo")
    exr = tmp_path / "aov.exr"
    run_cli("render", CORNELL, "-o", exr, "--quiet", "--width", 20, "--spp", 2,
            "--max-depth", 3, "--aov", "albedo")
    for c, name in enumerate("RGB"):
        layer = np.array(wf._core.read_exr_channel(str(exr), "Denoising Albedo." + name))
        assert np.array_equal(layer.reshape(out.image.shape[:2]), out.aov["albedo"][..., c])


def test_different_seeds_differ(renderer, cornell):
    a = renderer.render(cornell, width=16, spp=2, max_depth=3, seed=1).image
    b = renderer.render(cornell, width=16, spp=2, max_depth=3, seed=2).image
    again = renderer.render(cornell, width=16, spp=2, max_depth=3, seed=1).image
    assert not np.array_equal(a, b)
    assert np.array_equal(a, again)


def test_relmse_falls_about_as_one_over_spp(renderer, cornell):
    # Independent samples: the error of the mean falls exactly as 1/N in expectation, so the
    # fitted slope of log relMSE against log spp sits near -1 (the reference's own noise, at
    # 16x the largest count, flattens it by a few per cent).
    size = dict(width=24, max_depth=3, sampler="independent")
    reference = renderer.render(cornell, spp=1024, seed=99, **size).image
    counts = [4, 16, 64]
    errors = [np.mean([wf.relmse(renderer.render(cornell, spp=n, seed=s, **size).image,
                                 reference) for s in range(3)]) for n in counts]
    slope = np.polyfit(np.log(counts), np.log(errors), 1)[0]
    assert -1.25 < slope < -0.75, (errors, slope)
    assert wf.mse(reference, reference) == 0.0


def test_progressive_passes_end_at_renders_image(renderer, cornell):
    flags = dict(width=16, max_depth=3, seed=5)
    passes = list(renderer.render_progressive(cornell, spp=10, pass_spp=4, **flags))
    assert [p.spp for p in passes] == [4, 8, 10]
    whole = renderer.render(cornell, spp=10, **flags).image
    assert np.array_equal(passes[-1].image, whole)


def test_progressive_ended_by_another_render(renderer, cornell):
    passes = renderer.render_progressive(cornell, spp=8, pass_spp=2, width=8, max_depth=2)
    next(passes)
    renderer.render(cornell, spp=1, width=8, max_depth=2)
    with pytest.raises(RuntimeError, match="ended by another call"):
        next(passes)


def test_adaptive_render(renderer, cornell):
    out = renderer.render(cornell, width=16, spp=16, max_depth=3, target_error=0.05,
                          aov="samples")
    assert out.stats["adaptive"]["targetError"] == 0.05
    assert out.aov["samples"].max() <= 16 and 1 <= out.spp <= 16
    # targetMet comes from the image's own estimate, as the CLI's JSON says it: calibrated by
    # two error replicates, and with 4 of its standard errors to spare
    estimate = out.stats["errorEstimate"]
    assert estimate["replicates"] == 2 and estimate["upperBound"] is False
    assert out.stats["adaptive"]["targetMet"] == (
        estimate["reliable"] and estimate["relMse"] + 4 * estimate["standardError"] <= 0.05)


def test_every_render_estimates_its_error(renderer, cornell):
    out = renderer.render(cornell, width=16, spp=16, max_depth=3)
    estimate = out.stats["errorEstimate"]
    assert estimate["relMse"] > 0 and estimate["upperBound"] is True
    independent = renderer.render(cornell, width=16, spp=16, max_depth=3, sampler="independent")
    assert independent.stats["errorEstimate"]["upperBound"] is False
    # Two error replicates: calibrated, not a bound; one sequence's image is unchanged by asking
    # for one replicate.
    replicated = renderer.render(cornell, width=16, spp=16, max_depth=3, error_replicates=2)
    assert replicated.stats["errorEstimate"]["upperBound"] is False
    assert replicated.stats["errorEstimate"]["replicates"] == 2
    one = renderer.render(cornell, width=16, spp=16, max_depth=3, error_replicates=1)
    assert (one.image == out.image).all()
    with pytest.raises(ValueError, match="error_replicates"):
        renderer.render(cornell, width=16, spp=16, error_replicates=17)


def test_target_error_with_a_time_limit(renderer, cornell):
    out = renderer.render(cornell, width=16, spp=100000, max_depth=2, target_error=1e-9,
                          time_limit=0.5)
    assert out.stats["adaptive"]["stoppedBy"] == "time-limit"
    assert out.stats["adaptive"]["targetMet"] is False


def test_time_limit_stops_early(renderer, cornell):
    out = renderer.render(cornell, width=16, spp=100000, max_depth=2, time_limit=0.001)
    assert 1 <= out.spp < 100000


def test_traversal_as_the_cli(renderer, cornell, tmp_path):
    # auto on lavapipe and bvh trace the BVH; rt, where the device has ray-tracing pipelines,
    # gives the CLI's rt image bit for bit and says so in the stats; elsewhere DeviceError.
    out = renderer.render(cornell, width=16, spp=2, max_depth=3)
    assert out.stats["traversal"]["mode"] in ("bvh", "rt")
    with pytest.raises(ValueError):
        wf.Renderer(traversal="embree")
    try:
        rt = wf.Renderer(validation=True, traversal="rt")
    except wf.DeviceError as error:
        assert "ray-tracing pipelines" in str(error)
        return
    with rt:
        out = rt.render(cornell, width=16, spp=2, max_depth=3, seed=5)
        stats = out.stats
        assert stats["traversal"]["mode"] == "rt"
        assert stats["traversal"]["accelerationBytes"] > 0
        cli = cli_render(tmp_path, "rt", "--width", 16, "--spp", 2, "--max-depth", 3,
                         "--seed", 5, "--traversal", "rt")
        assert np.array_equal(cli.view(np.uint32), out.image.view(np.uint32))
        assert rt.validation_messages == 0


def test_animation_time_as_the_cli(renderer, tmp_path):
    # time / frame / fps / animation pose the scene at load, as render's flags do: another time
    # is another image, and each is the CLI's at that time bit for bit.
    arm = CORNELL.parent / "animated_arm.gltf"
    flags = dict(width=24, spp=2, max_depth=3, seed=4)
    early = renderer.render(renderer.load(arm, time=0.25), **flags).image
    late = renderer.render(renderer.load(arm, frame=30, fps=24, animation="play"), **flags).image
    assert not np.array_equal(early, late)
    for image, when in ((early, ["--time", "0.25"]), (late, ["--frame", "30", "--fps", "24"])):
        out = tmp_path / "arm.exr"
        run_cli("render", arm, "-o", out, "--quiet", "--width", 24, "--spp", 2,
                "--max-depth", 3, "--seed", 4, *when)
        cli = wf.read_exr(out)[0]
        assert np.array_equal(cli.view(np.uint32), image.view(np.uint32))
    # The same refusals as the CLI's, in keywords.
    with pytest.raises(ValueError, match="time and frame"):
        renderer.load(arm, time=1.0, frame=3)
    with pytest.raises(wf.SceneError, match="no such animation"):
        renderer.load(arm, animation="walk")


def variants_file(path):
    """One emissive triangle: white, red in variant "red", blue in variant "blue" (the file
    tests/cli/variants_gltf.py writes for the CLI and viewer checks)."""
    script = Path(__file__).resolve().parents[1] / "cli" / "variants_gltf.py"
    subprocess.run([sys.executable, str(script), str(path)], check=True)
    return path


def test_material_variants(renderer, tmp_path):
    path = variants_file(tmp_path / "variants.gltf")
    flags = dict(width=8, spp=1, max_depth=1)
    own = renderer.load(path)
    assert own.info["variants"] == ["red", "blue"] and own.info["variant"] is None
    blue = renderer.load(path, variant="blue")
    assert blue.info["variant"] == 1
    assert renderer.load(path, variant=0).info["variant"] == 0
    sums = [renderer.render(s, **flags).image[..., :3].sum(axis=(0, 1))
            for s in (own, blue, renderer.load(path, variant="red"))]
    assert sums[0].min() > 0                        # white: every channel
    assert sums[1][0] == sums[1][1] == 0 < sums[1][2]  # blue only
    assert sums[2][1] == sums[2][2] == 0 < sums[2][0]  # red only
    with pytest.raises(wf.SceneError, match="no such variant"):
        renderer.load(path, variant="green")


def test_light_tracing_from_the_renderer_or_the_call(renderer, cornell):
    path = renderer.render(cornell, width=16, spp=64, max_depth=4, seed=3)
    light = renderer.render(cornell, width=16, spp=64, max_depth=4, seed=3, integrator="light")
    # Another estimator of the same image: equal means within a few per cent, unequal pixels.
    assert abs(light.image.mean() / path.image.mean() - 1.0) < 0.05
    assert not np.array_equal(light.image, path.image)
    assert np.isfinite(light.image).all()
    with wf.Renderer(integrator="light") as own:
        again = own.render(own.load(CORNELL), width=16, spp=64, max_depth=4, seed=3)
        assert np.array_equal(again.image, light.image)  # same seed, same image
        with pytest.raises(ValueError, match="target_error"):
            own.render(own.load(CORNELL), width=16, target_error=0.01)
    with pytest.raises(ValueError, match="integrator"):
        wf.Renderer(integrator="sppm")
    vcm = renderer.render(cornell, width=16, spp=2, max_depth=4, integrator="vcm", vcm_radius=0.05)
    assert np.isfinite(vcm.image).all() and vcm.image.mean() > 0.0
    # light_share as --light-share: one light subpath per pixel is another image of bdpt's.
    shared = renderer.render(cornell, width=16, spp=4, max_depth=4, integrator="bdpt", seed=5)
    own = renderer.render(cornell, width=16, spp=4, max_depth=4, integrator="bdpt", seed=5,
                          light_share=1)
    assert not np.array_equal(shared.image, own.image)
    with pytest.raises(ValueError, match="light_share"):
        renderer.render(cornell, width=16, spp=1, integrator="path", light_share=2)
