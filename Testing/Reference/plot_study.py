"""Pareto plots and markdown table of a VoxelGIErrorStudy CSV.

    python3 plot_study.py STUDY.csv OUT.png OUT.md "machine label" "scene title"

A configuration is on a Pareto front when no other one is both at least as fast and at least as
close to the reference (by FLIP), and better in one of the two. Two fronts: against the time of
a full update (voxelize, light, mip, trace) and against the time of a camera-only frame (the
voxels are reused: only tracing and compositing run).
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

study, png, md, machine, title = sys.argv[1:6]
with open(study) as f:
    rows = list(csv.DictReader(f))
for r in rows:
    for key in ("frame_ms", "camera_ms", "rmse", "relmse", "ssim", "flip"):
        r[key] = float(r[key])
    r["label"] = r["config"] if not r["setting"] else "%s=%g" % (r["setting"], float(r["value"]))
    r["baseline"] = r["config"] in ("plain", "ssao", "gi-off")


def pareto(time):
    for r in rows:
        r["pareto_" + time] = not any(
            o[time] <= r[time] and o["flip"] <= r["flip"] and
            (o[time] < r[time] or o["flip"] < r["flip"]) for o in rows)


pareto("frame_ms")
pareto("camera_ms")

fig, axes = plt.subplots(1, 3, figsize=(18, 5.5))
panels = (("frame_ms", "flip", "full update"), ("frame_ms", "relmse", "full update"),
          ("camera_ms", "flip", "camera only"))
for ax, (time, metric, kind) in zip(axes, panels):
    front_key = "pareto_" + time
    for r in rows:
        ax.scatter(r[time], r[metric], color="tab:red" if r["baseline"] else "tab:blue",
                   marker="s" if r["baseline"] else "o",
                   edgecolors="black" if r[front_key] else "none")
        ax.annotate(r["label"], (r[time], r[metric]), fontsize=6, xytext=(3, 3),
                    textcoords="offset points")
    front = sorted((r for r in rows if r[front_key]), key=lambda r: r[time])
    ax.plot([r[time] for r in front], [r[metric] for r in front], color="gray", lw=0.8)
    ax.set_xscale("log")
    if metric == "relmse":
        ax.set_yscale("log")  # the baselines are often ten times worse
    ax.set_xlabel("frame time, %s, ms (%s)" % (kind, machine))
    ax.set_ylabel("FLIP" if metric == "flip" else "relMSE")
    ax.grid(True, which="both", lw=0.3)
axes[0].set_title("%s: error vs Cycles against frame time" % title)
axes[1].set_title("red squares: baselines; outlined: Pareto front by FLIP")
axes[2].set_title("camera-only frames (voxels reused)")
fig.tight_layout()
fig.savefig(png, dpi=100)

with open(md, "w") as f:
    f.write("| configuration | full update ms | camera-only ms | RMSE | relMSE | SSIM | FLIP "
            "| Pareto (full) | Pareto (camera) |\n")
    f.write("|---|---|---|---|---|---|---|---|---|\n")
    for r in rows:
        f.write("| %s | %.1f | %.1f | %.3f | %.3f | %.3f | %.3f | %s | %s |\n" % (
            r["label"], r["frame_ms"], r["camera_ms"], r["rmse"], r["relmse"], r["ssim"],
            r["flip"], "yes" if r["pareto_frame_ms"] else "",
            "yes" if r["pareto_camera_ms"] else ""))
