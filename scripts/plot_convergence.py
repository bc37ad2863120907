#!/usr/bin/python3
"""Charts of a `wavefront converge` run, drawn with matplotlib (Debian: python3-matplotlib).

Usage: plot_convergence.py DIR [--title TEXT]

Reads DIR/convergence.json and writes
  DIR/error_vs_time.png  relMSE against GPU time, log-log, one line per method
  DIR/error_vs_spp.png   relMSE against samples per pixel, log-log
  DIR/equal_time.png     the equal-time crops of DIR/crops/, one per method
Lines are medians across seeds, bands the interquartile range; the dashed grey line has
slope -1 (Monte Carlo's 1/N), the dotted one marks the ranking's target relMSE.
"""
import json
import os
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.image as mpimg
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit("plot_convergence.py: matplotlib is missing; on Debian: apt-get install "
             "python3-matplotlib")

STYLE = {"mis": "-", "nee": "--", "bsdf": ":"}


def method_style(index, method):
    colors = plt.get_cmap("tab10").colors
    return {"color": colors[index % len(colors)],
            "linestyle": STYLE.get(method["lightSampling"], "-"),
            "marker": "o", "markersize": 3, "linewidth": 1.5}


def error_chart(run, key, xlabel, path, title):
    fig, ax = plt.subplots(figsize=(9.0, 4.4))
    all_x = []
    for i, m in enumerate(run["methods"]):
        x, y = m[key], m["relMse"]
        pairs = [(a, b, lo, hi) for a, b, lo, hi in zip(x, y, m["relMseQ1"], m["relMseQ3"])
                 if a is not None and b is not None and a > 0 and b > 0]
        if not pairs:
            continue
        xs, ys, los, his = zip(*pairs)
        all_x += xs
        style = method_style(i, m)
        ax.plot(xs, ys, label="%s (slope %.2f)" % (m["name"], m["slopeSpp"]), **style)
        ax.fill_between(xs, los, his, color=style["color"], alpha=0.15, linewidth=0)
        # The renders' own estimate beside the measured error: how far their error bars hold
        # (hollow markers where fewer than half the seeds called it reliable).
        est = [(a, e, r) for a, e, r in zip(x, m.get("estimatedRelMse", []),
                                            m.get("estimateReliable", []))
               if a is not None and e is not None and a > 0 and e > 0]
        if est:
            ex, ey, er = zip(*est)
            ax.plot(ex, ey, color=style["color"], linestyle=":", linewidth=1)
            ax.scatter(ex, ey, s=12, marker="s", color=style["color"], zorder=3,
                       facecolors=[style["color"] if r >= 0.5 else "none" for r in er])
    if all_x and run["methods"]:
        # 1/N through the first method's first point, across the whole x range.
        first = run["methods"][0]
        x0, y0 = first[key][0], first["relMse"][0]
        if x0 and y0:
            xs = [min(all_x), max(all_x)]
            ax.plot(xs, [y0 * x0 / x for x in xs], color="0.5", linestyle="--", linewidth=1,
                    label="slope -1 (1/N)")
    if run.get("target"):
        ax.axhline(run["target"], color="0.3", linestyle=":", linewidth=1,
                   label="target relMSE %.3g" % run["target"])
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel("relMSE (median, IQR band); dotted: own estimate")
    ax.set_title(title, fontsize=10)
    ax.grid(True, which="both", alpha=0.25)
    # Outside the axes: inside, it hides the curves of some scenes.
    ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    plt.close(fig)


def crop_chart(run, folder, path, title):
    crops = run.get("equalTimeCrops", [])
    if not crops:
        return
    columns = min(len(crops), 5)
    rows = (len(crops) + columns - 1) // columns
    fig, axes = plt.subplots(rows, columns, figsize=(2.0 * columns, 2.25 * rows + 0.3),
                             squeeze=False)
    for ax in axes.flat:
        ax.axis("off")
    for ax, crop in zip(axes.flat, crops):
        ax.imshow(mpimg.imread(os.path.join(folder, crop["file"])), interpolation="nearest")
        label = crop["method"] if crop["method"] == "reference" else "%s\n%d spp, %.2f s" % (
            crop["method"], crop["spp"], crop["gpuSeconds"])
        ax.set_title(label, fontsize=7)
    fig.suptitle(title, fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    plt.close(fig)


def main(argv):
    if len(argv) < 2 or argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0 if len(argv) >= 2 else 2
    folder = argv[1]
    title = argv[argv.index("--title") + 1] if "--title" in argv else None
    with open(os.path.join(folder, "convergence.json")) as f:
        run = json.load(f)
    name = title or os.path.basename(run["scene"])
    caption = "%s, %dx%d, %d seeds, reference: %s" % (
        name, run["width"], run["height"], len(run["seeds"]),
        run["reference"]["method"] + (" %d spp" % run["reference"]["spp"]
                                      if run["reference"]["spp"] else ""))
    error_chart(run, "gpuSeconds", "GPU time (s, timestamp queries)",
                os.path.join(folder, "error_vs_time.png"), caption)
    error_chart(run, "spp", "samples per pixel", os.path.join(folder, "error_vs_spp.png"),
                caption)
    crop_chart(run, folder, os.path.join(folder, "equal_time.png"),
               "%s: equal GPU time crops" % name)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
