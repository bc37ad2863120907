"""Path guiding from Python: wf.Renderer(guiding=...) is every render's default, render()
may override it, auto's decision is in the stats, and the guided image is the CLI's."""
import numpy as np
import pytest

import wavefront as wf

from conftest import CORNELL, SCENES, run_cli


def test_guiding_default_is_auto_and_says_why(renderer, cornell):
    out = renderer.render(cornell, width=16, spp=8, max_depth=3)
    assert out.stats["guidingDecision"].startswith("auto: off")
    assert "guiding" not in out.stats  # nothing trained


def test_guided_render_matches_the_cli(renderer, tmp_path):
    caustic = renderer.load(SCENES / "glass_caustic.gltf")
    out = renderer.render(caustic, width=24, spp=16, max_depth=4, seed=3, guiding="on")
    assert out.stats["guidingDecision"] == "on (asked)"
    # Iterations of 1, 2, 4 spp, then 9: the image is the mean of all 16 samples.
    assert out.stats["guiding"]["iterations"] == 3 and out.stats["guiding"]["imageSpp"] == 16
    assert out.stats["guiding"]["stoppedUnused"] is False  # the budget ended training first
    assert np.isfinite(out.image).all() and out.image.mean() > 0
    path = tmp_path / "guided.exr"
    run_cli("render", SCENES / "glass_caustic.gltf", "-o", path, "--quiet", "--width", "24",
            "--spp", "16", "--max-depth", "4", "--seed", "3", "--guiding", "on")
    assert np.array_equal(out.image, wf.read_exr(path)[0])


def test_training_stops_where_the_guide_does_not_pay(renderer, cornell):
    # The Cornell box's leaves learn BSDF share 1: at 64x64 training ends after 1 + 2 + 4 spp.
    out = renderer.render(cornell, width=64, height=64, spp=32, max_depth=6, seed=1,
                          guiding="on")
    assert out.stats["guiding"]["stoppedUnused"] is True
    assert out.stats["guiding"]["iterations"] == 3 and out.stats["guiding"]["imageSpp"] == 32


def test_renderer_wide_guiding_and_override():
    with wf.Renderer(guiding="on") as r:
        scene = r.load(CORNELL)
        guided = r.render(scene, width=16, spp=8, max_depth=3)
        assert guided.stats["guidingDecision"] == "on (asked)"
        off = r.render(scene, width=16, spp=8, max_depth=3, guiding="off")
        assert off.stats["guidingDecision"] == "off (asked)"
        with pytest.raises(ValueError, match="render_progressive does not guide"):
            next(r.render_progressive(scene, spp=8, width=16))


def test_bad_guiding_words():
    with pytest.raises(ValueError, match="guiding"):
        wf.Renderer(guiding="yes")


def test_guided_target_error_trains_the_guide_as_the_pilot(renderer):
    caustic = renderer.load(SCENES / "glass_caustic.gltf")
    out = renderer.render(caustic, width=24, spp=64, max_depth=4, seed=3, guiding="on",
                          target_error=0.05)
    # The pilot is the training's iterations of 1, 2 and 4 spp (pilotSppFor(64) = 4).
    assert out.stats["guiding"]["iterations"] >= 3
    assert out.stats["adaptive"]["pilotSpp"] >= 4
    assert np.isfinite(out.image).all() and out.image.mean() > 0
