"""Pareto plot and markdown table of a VoxelGIErrorStudy CSV.

    python3 plot_study.py STUDY.csv OUT.png OUT.md "machine label"

A configuration is on the Pareto front when no other one is both faster and closer to the
reference (by FLIP).
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

study, png, md, machine = sys.argv[1:5]
with open(study) as f:
    rows = list(csv.DictReader(f))
for r in rows:
    for key in ("frame_ms", "rmse", "relmse", "ssim", "flip"):
        r[key] = float(r[key])
    r["label"] = r["config"] if not r["setting"] else "%s=%g" % (r["setting"], float(r["value"]))
for r in rows:
    r["pareto"] = not any(o["frame_ms"] <= r["frame_ms"] and o["flip"] <= r["flip"] and
                          (o["frame_ms"] < r["frame_ms"] or o["flip"] < r["flip"]) for o in rows)

fig, axes = plt.subplots(1, 2, figsize=(13, 5.5))
for ax, metric in zip(axes, ("flip", "relmse")):
    for r in rows:
        gi = r["config"] not in ("plain", "ssao", "gi-off")
        ax.scatter(r["frame_ms"], r[metric], color="tab:blue" if gi else "tab:red",
                   marker="o" if gi else "s", edgecolors="black" if r["pareto"] else "none")
        ax.annotate(r["label"], (r["frame_ms"], r[metric]), fontsize=6, xytext=(3, 3),
                    textcoords="offset points")
    front = sorted((r for r in rows if r["pareto"]), key=lambda r: r["frame_ms"])
    ax.plot([r["frame_ms"] for r in front], [r[metric] for r in front], color="gray", lw=0.8)
    ax.set_xscale("log")
    ax.set_xlabel("frame time, full update, ms (%s)" % machine)
    ax.set_ylabel(metric.upper() if metric == "flip" else "relMSE")
    ax.grid(True, which="both", lw=0.3)
axes[0].set_title("Cornell box: error vs Cycles reference against frame time")
axes[1].set_title("red squares: baselines; outlined: Pareto front (FLIP)")
fig.tight_layout()
fig.savefig(png, dpi=110)

with open(md, "w") as f:
    f.write("| configuration | frame ms | RMSE | relMSE | SSIM | FLIP | Pareto (FLIP) |\n")
    f.write("|---|---|---|---|---|---|---|\n")
    for r in rows:
        f.write("| %s | %.1f | %.3f | %.3f | %.3f | %.3f | %s |\n" % (
            r["label"], r["frame_ms"], r["rmse"], r["relmse"], r["ssim"], r["flip"],
            "yes" if r["pareto"] else ""))
