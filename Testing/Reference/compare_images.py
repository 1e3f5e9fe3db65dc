"""Side-by-side figure of the path-traced references and the study's images: per scene, the
Cycles reference, plain VTK, VTK's SSAO, the pass at its defaults, and |defaults - reference|.

    python3 compare_images.py OUT.png STUDY_PREFIX SCENE... [--references DIR]

reads DIR/SCENE.pfm (default Testing/Data/Reference) and
STUDY_PREFIX-SCENE-{plain,ssao,defaults}.pfm (written by VoxelGIErrorStudy). All images are linear radiance shown clamped to [0, 1] and sRGB-encoded,
the way the references' PNG previews are.
"""
import os
import sys

import matplotlib
import numpy as np

from float_images import read_pfm, srgb_encode

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

args = sys.argv[1:]
references = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Data", "Reference")
if "--references" in args:
    at = args.index("--references")
    references = args[at + 1]
    del args[at:at + 2]
out, prefix, scenes = args[0], args[1], args[2:]


def pfm(path):
    return read_pfm(path)[::-1]  # top row first, for imshow


def display(linear):
    return srgb_encode(np.clip(linear, 0.0, 1.0))


columns = ("Cycles reference", "plain VTK", "vtkSSAOPass", "voxel GI, defaults",
           "|GI - reference| x 2")
fig, axes = plt.subplots(len(scenes), len(columns), figsize=(2.4 * len(columns), 2.5 * len(scenes)),
                         squeeze=False)
for row, scene in enumerate(scenes):
    reference = pfm(os.path.join(references, scene + ".pfm"))
    images = [reference] + [pfm("%s-%s-%s.pfm" % (prefix, scene, c))
                            for c in ("plain", "ssao", "defaults")]
    images.append(2.0 * np.abs(images[3] - reference))
    for col, image in enumerate(images):
        ax = axes[row][col]
        ax.imshow(display(image))
        ax.set_xticks([])
        ax.set_yticks([])
        if row == 0:
            ax.set_title(columns[col], fontsize=9)
        if col == 0:
            ax.set_ylabel(scene, fontsize=9)
fig.tight_layout()
fig.savefig(out, dpi=100)
