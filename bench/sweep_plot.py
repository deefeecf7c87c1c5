#!/usr/bin/python3
"""Plots bench/sweep.sh's CSV: is raytex's frame time linear in pixels and in samples per pixel?

Panel (a): GPU frame time against pixels at spp 1; panel (b): against spp at 1920x1080 (else
the largest size in the CSV). One series per sphere material, log-log, each with its
least-squares line through the origin, frame_ms = slope * x (dashed). Prints per material the
slopes, ms per Mpixel and ms per Mpixel-sample, and the R^2 of each through-origin fit,
computed against the mean (1 - SS_res / sum (y - mean y)^2, so a poor fit scores low or
negative, not the inflated uncentred R^2), plus the intercept an unconstrained fit would give
(the fixed per-frame cost, which linearity says is ~0), and last one fit over all the
material's rows against Mpixel x spp.
Usage: bench/sweep_plot.py SWEEP.csv OUT.png
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def fit(x, y):
    """Through-origin slope, its centred R^2 and the intercept of the unconstrained line."""
    x, y = np.asarray(x, float), np.asarray(y, float)
    slope = float(x @ y / (x @ x))
    ss_tot = float(((y - y.mean()) ** 2).sum())
    r2 = 1 - float(((y - slope * x) ** 2).sum()) / ss_tot if len(x) > 1 and ss_tot > 0 else float("nan")
    intercept = float(np.polyfit(x, y, 1)[1]) if len(set(x.tolist())) > 1 else float("nan")
    return slope, r2, intercept


def series(ax, rows, xkey, xscale, label, style):
    """Plots one material's points and fit line on ax; returns the fit."""
    if not rows:
        return float("nan"), float("nan"), float("nan")
    rows = sorted(rows, key=lambda r: r[xkey])
    x = np.array([r[xkey] * xscale for r in rows])
    y = np.array([r["frame_ms"] for r in rows])
    ax.plot(x, y, linestyle="none", label=label, **style)
    slope, r2, intercept = fit(x, y)
    xs = np.geomspace(x.min(), x.max(), 20) if x.min() < x.max() else x
    ax.plot(xs, slope * xs, linestyle="--", linewidth=1, color=style["color"])
    return slope, r2, intercept


def main():
    source, chart = sys.argv[1:3]
    with open(source) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit("sweep_plot.py: no rows in " + source)
    for r in rows:
        for k in ("width", "height", "pixels", "spp"):
            r[k] = int(r[k])
        r["frame_ms"] = float(r["frame_ms"])
    materials = list(dict.fromkeys(r["material"] for r in rows))
    devices = ", ".join(dict.fromkeys(r["device"] for r in rows))
    sizes = {(r["width"], r["height"]) for r in rows}
    size = (1920, 1080) if (1920, 1080) in sizes else max(sizes, key=lambda s: s[0] * s[1])
    base_spp = 1 if any(r["spp"] == 1 for r in rows) else min(r["spp"] for r in rows)

    fig, (ax_a, ax_b) = plt.subplots(1, 2, figsize=(11, 4.6))
    print("through-origin least-squares fits of GPU frame time; R^2 centred; b = intercept of a free fit")
    print("%-13s %12s %7s %8s | %16s %7s %8s | %16s %7s" % (
        "material", "ms/Mpixel", "R^2", "b ms", "ms/Mpixel-sample", "R^2", "b ms", "all: ms/Mpx-smp", "R^2"))
    for i, m in enumerate(materials):
        style = {"color": plt.cm.tab10(i % 10), "marker": "osD^v<>p"[i % 8]}
        mine = [r for r in rows if r["material"] == m]
        a = series(ax_a, [r for r in mine if r["spp"] == base_spp], "pixels", 1e-6, m, style)
        at_size = [r for r in mine if (r["width"], r["height"]) == size]
        s = series(ax_b, at_size, "spp", 1, m, style)
        mpix = size[0] * size[1] / 1e6
        both = fit([r["pixels"] * r["spp"] / 1e6 for r in mine], [r["frame_ms"] for r in mine])
        print("%-13s %12.3f %7.4f %8.2f | %16.3f %7.4f %8.2f | %16.3f %7.4f" % (
            m, a[0] / base_spp, a[1], a[2], s[0] / mpix, s[1], s[2], both[0], both[1]))
    for ax in (ax_a, ax_b):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.grid(True, which="both", alpha=0.3)
        lo, hi = ax.get_ylim()
        subs = (1, 2, 3, 5) if hi / lo < 100 else (1, 2, 5) if hi / lo < 1e4 else (1,)
        ax.yaxis.set_major_locator(matplotlib.ticker.LogLocator(subs=subs))
        ax.yaxis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
        ax.yaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.set_ylabel("GPU frame time, median (ms)")
    ax_a.set_xlabel("pixels (millions)")
    swept = sorted({(r["width"], r["height"]) for r in rows if r["spp"] == base_spp}, key=lambda s: s[0] * s[1])
    ax_a.set_xticks([w * h / 1e6 for w, h in swept], ["%.2f\n%dx%d" % (w * h / 1e6, w, h) for w, h in swept])
    ax_a.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    ax_a.set_title("(a) frame time vs pixels, spp %d" % base_spp, fontsize=10)
    ax_b.set_xlabel("samples per pixel")
    ax_b.set_xticks(sorted({r["spp"] for r in rows}))
    ax_b.xaxis.set_major_formatter(matplotlib.ticker.ScalarFormatter())
    ax_b.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    ax_b.set_title("(b) frame time vs spp, %dx%d" % size, fontsize=10)
    ax_b.legend(title="sphere material", fontsize=8, title_fontsize=8, loc="upper left",
                bbox_to_anchor=(1.02, 1.0), borderaxespad=0)
    fig.suptitle("raytex bench sweep, course scene (dashed: least-squares line through the origin)\n"
                 "device: %s" % devices, fontsize=10)
    fig.tight_layout()
    fig.savefig(chart, dpi=110)
    print("wrote", chart)


if __name__ == "__main__":
    main()
