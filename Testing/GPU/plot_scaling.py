#!/usr/bin/python3
"""Plot the scaling benchmark (run_scaling_benchmark.sh): full-dynamic frame cost against the
number of actors and against the number of triangles, with plain VTK's frame of the same run.
With --voxelization, the sweep of run_scale_benchmark.sh instead: voxelization time and frame
against triangles, by compute and through VTK's mappers (the JSON's ComputeVoxelization).

Usage: plot_scaling.py [--voxelization] OUT.png FILE.json [FILE.json ...]
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def load(paths):
    runs = []
    for path in paths:
        with open(path) as f:
            runs.append(json.load(f))
    return runs


def value(medians, key):
    # Voxelization: the static and the dynamic draws together.
    if key == "Voxelize":
        return medians["VoxelizeStatic"] + medians["VoxelizeDynamic"]
    return medians[key]


def series(runs, scene, resolution, key, sequence):
    points = sorted(
        ((r["actors"] if scene == "field" else r["triangles"]),
         value(r["median_ms"][sequence], key))
        for r in runs if r["scene"] == scene and r["resolution"] == resolution)
    return [p[0] for p in points], [p[1] for p in points]


def plot_voxelization(out, runs):
    fig, ax = plt.subplots(figsize=(7, 4.8))
    for compute, path, colour in ((1, "compute", "C0"), (0, "VTK's mappers", "C3")):
        chosen = sorted((r for r in runs if r["settings"].get("ComputeVoxelization") == compute),
                        key=lambda r: r["triangles"])
        x = [r["triangles"] for r in chosen]
        for key, style, name in (("Voxelize", "-", "voxelization (GPU)"), ("frame", "--", "GI frame")):
            ax.plot(x, [value(r["median_ms"]["all-moving"], key) for r in chosen], style,
                    marker="o", color=colour, label=f"{name}, {path}")
        if compute:
            ax.plot(x, [r["median_ms"]["plain"]["frame"] for r in chosen], ":", marker="o",
                    color="k", label="plain VTK frame")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("triangles (one sphere that moves every frame), 128³ voxels")
    ax.set_ylabel("ms per frame (median)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title(f"Voxelization against triangles, 1920×1080, {runs[0]['renderer']}", fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    return 0


def main():
    args = [a for a in sys.argv[1:] if a != "--voxelization"]
    if len(args) < 2:
        print(__doc__)
        return 2
    runs = load(args[1:])
    if "--voxelization" in sys.argv:
        return plot_voxelization(args[0], runs)
    resolutions = sorted({r["resolution"] for r in runs})
    machine = runs[0]["renderer"]
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.8))
    for ax, scene, label in ((axes[0], "field", "actors (field of spheres and boxes)"),
                             (axes[1], "sphere", "triangles (one sphere)")):
        for i, res in enumerate(resolutions):
            style = "-" if i == 0 else "--"
            for key, sequence, name, colour in (
                    ("frame", "all-moving", "GI frame", "C0"),
                    ("cpu", "all-moving", "GI CPU in Render()", "C1"),
                    ("gpu_span", "all-moving", "GI GPU span", "C2"),
                    ("Voxelize", "all-moving", "Voxelize (GPU)", "C3"),
                    ("frame", "plain", "plain VTK frame", "k")):
                x, y = series(runs, scene, res, key, sequence)
                if x:
                    ax.plot(x, y, style, marker="o", color=colour, label=f"{name}, {res}³")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel(label)
        ax.set_ylabel("ms per frame (median)")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_title("every actor moves, each frame")
    axes[1].set_title("the sphere moves, each frame")
    axes[1].legend(fontsize=7, ncol=2)
    fig.suptitle(f"Full-dynamic frames, 1920×1080, {machine}")
    fig.tight_layout()
    fig.savefig(args[0], dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main())
