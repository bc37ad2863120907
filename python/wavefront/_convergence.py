"""Renderer.converge()'s result: one record per method, seed and checkpoint, as the rows of
`wavefront converge`'s convergence.csv, with the medians and the chart of its error_vs_time.png.
"""
import csv
import statistics

CSV_COLUMNS = ("method", "sampler", "light_sampling", "seed_index", "spp", "gpu_seconds",
               "wall_seconds", "relmse", "mse", "bias")


class ConvergenceRuns:
    """A list of records (dicts): method, sampler, light_sampling, seed, seed_index, spp,
    gpu_seconds, wall_seconds, relmse, mse, bias."""

    def __init__(self, records):
        self.records = list(records)

    def __len__(self):
        return len(self.records)

    def __iter__(self):
        return iter(self.records)

    def __getitem__(self, index):
        return self.records[index]

    def __repr__(self):
        return f"<ConvergenceRuns: {len(self.records)} records of {', '.join(self.methods)}>"

    @property
    def methods(self):
        """The methods in the order they ran."""
        return list(dict.fromkeys(r["method"] for r in self.records))

    def medians(self, method, x="gpu_seconds"):
        """[(spp, median x, median relMSE)] over the seeds, per checkpoint."""
        by_spp = {}
        for r in self.records:
            if r["method"] == method:
                by_spp.setdefault(r["spp"], []).append(r)
        return [(spp, statistics.median(r[x] for r in rs),
                 statistics.median(r["relmse"] for r in rs))
                for spp, rs in sorted(by_spp.items())]

    def to_csv(self, path):
        """The CLI's convergence.csv, column for column (numbers to 6 significant digits)."""
        with open(path, "w", newline="") as out:
            writer = csv.writer(out, lineterminator="\n")
            writer.writerow(CSV_COLUMNS)
            for r in self.records:
                writer.writerow([r[c] if not isinstance(r[c], float) else "%.6g" % r[c]
                                 for c in CSV_COLUMNS])

    def plot(self, ax=None, x="gpu_seconds", path=None):
        """relMSE against time (x="gpu_seconds" or "wall_seconds") or samples (x="spp"),
        log-log, the median over seeds per method, with the slope -1 of Monte Carlo's 1/N.
        Draws on `ax` (a new figure when None), saves the figure to `path` when given, and
        returns the axes. Needs matplotlib (Debian: python3-matplotlib)."""
        import matplotlib
        if ax is None and path is not None:
            matplotlib.use("Agg", force=False)
        import matplotlib.pyplot as plt
        if x not in ("gpu_seconds", "wall_seconds", "spp"):
            raise ValueError(f"x is gpu_seconds, wall_seconds or spp, not {x!r}")
        if ax is None:
            _, ax = plt.subplots(figsize=(7.5, 4.2))
        first = None
        for method in self.methods:
            points = [(t, e) for _, t, e in self.medians(method, x) if t > 0 and e > 0]
            if not points:
                continue
            xs, ys = zip(*points)
            ax.plot(xs, ys, marker="o", markersize=3, label=method)
            first = first or (xs, ys)
        if first:
            xs, ys = first
            ends = [min(xs), max(xs)]
            ax.plot(ends, [ys[0] * xs[0] / t for t in ends], color="0.5", linestyle="--",
                    linewidth=1, label="slope -1 (1/N)")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel({"gpu_seconds": "GPU seconds", "wall_seconds": "wall seconds",
                       "spp": "samples per pixel"}[x])
        ax.set_ylabel("relMSE (median over seeds)")
        ax.grid(True, which="both", alpha=0.25)
        ax.legend(fontsize=8)
        if path is not None:
            ax.figure.tight_layout()
            ax.figure.savefig(path, dpi=100)
        return ax
