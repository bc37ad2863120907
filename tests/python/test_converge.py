"""converge(): the CLI's CSV rows for the same seeds; plot() draws the chart."""
import csv

import pytest

import wavefront as wf
from conftest import CORNELL, run_cli


def test_converge_records_agree_with_the_cli_csv(renderer, cornell, tmp_path):
    reference = renderer.render(cornell, width=16, spp=64, max_depth=3, seed=77).image
    ref_path = tmp_path / "ref.exr"
    wf.write_exr(ref_path, reference)
    # A time budget no checkpoint reaches: the checkpoints are 1, 2, 4 spp (max_spp) for both.
    runs = renderer.converge(cornell, reference=ref_path, methods=["sobol", "independent+nee"],
                             seeds=range(1, 6), time=1e6, max_spp=4, max_depth=3)
    run_cli("converge", CORNELL, "-o", tmp_path / "cli", "--reference", ref_path,
            "--methods", "sobol,independent+nee", "--seeds", 5, "--time", 1e6, "--max-spp", 4,
            "--max-depth", 3, "--no-plot", "--quiet")
    with open(tmp_path / "cli" / "convergence.csv") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == len(runs) == 2 * 5 * 3
    for row, record in zip(rows, runs):
        assert row["method"] == record["method"] and row["sampler"] == record["sampler"]
        assert int(row["seed_index"]) == record["seed_index"]
        assert int(row["spp"]) == record["spp"]
        for column in ("relmse", "mse", "bias"):
            assert row[column] == "%.6g" % record[column], (column, row, record)
    assert runs.methods == ["sobol+mis", "independent+nee"]
    runs.to_csv(tmp_path / "again.csv")
    with open(tmp_path / "again.csv") as f:
        again = list(csv.DictReader(f))
    for a, b in zip(again, rows):
        for column in ("method", "seed_index", "spp", "relmse", "mse", "bias"):
            assert a[column] == b[column]


def test_plot_writes_a_figure(renderer, cornell, tmp_path):
    runs = renderer.converge(cornell, reference=16, methods=["sobol", "independent"],
                             seeds=[1, 2], checkpoints=[1, 2, 4], width=12, max_depth=2)
    assert {r["spp"] for r in runs} == {1, 2, 4} and len(runs) == 2 * 2 * 3
    medians = runs.medians("sobol+mis", x="spp")
    assert [m[0] for m in medians] == [1, 2, 4]
    chart = tmp_path / "chart.png"
    ax = runs.plot(path=chart)
    assert chart.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert len(ax.get_lines()) == 3  # two methods and the 1/N guide


def test_converge_refusals(renderer, cornell):
    with pytest.raises(ValueError, match="unknown"):
        renderer.converge(cornell, reference=4, methods=["sobol+warp"], seeds=[1], width=8)
    with pytest.raises(ValueError, match="shape"):
        renderer.converge(cornell, reference=[[1.0]], methods=["sobol"], seeds=[1])
    with pytest.raises(ValueError, match="converge renders"):
        import numpy as np
        renderer.converge(cornell, reference=np.zeros((4, 4, 3)), methods=["sobol"],
                          seeds=[1], width=8, height=8)
