"""The committed scene descriptions (Testing/Data/Scenes), from which the path-traced references
were rendered, must still describe the built-in scenes: a scene changed in C++ without
re-exporting and re-rendering would leave its reference stale.

    python3 test_scene_descriptions.py EXPORT_SCRIPT SCENES_DIR TMP_DIR
"""
import json
import math
import os
import subprocess
import sys

export, scenes, tmp = sys.argv[1:4]
os.makedirs(tmp, exist_ok=True)


def numbers_close(a, b):
    """JSON values equal, numbers to 1e-9 relative."""
    if isinstance(a, dict):
        return isinstance(b, dict) and a.keys() == b.keys() and \
            all(numbers_close(a[k], b[k]) for k in a)
    if isinstance(a, list):
        return isinstance(b, list) and len(a) == len(b) and \
            all(numbers_close(x, y) for x, y in zip(a, b))
    if isinstance(a, (int, float)) and isinstance(b, (int, float)):
        return math.isclose(a, b, rel_tol=1e-9, abs_tol=1e-12)
    return a == b


failures = []
for scene in ("cornell", "glossy", "isosurface", "glyphs", "emissive", "streamlines", "volume",
              "pointroom", "lamproom", "emitterroom", "volumeroom", "contacts", "contactsheadlight",
              "translucent"):
    prefix = os.path.join(tmp, scene)
    subprocess.run([sys.executable, export, scene, prefix], check=True)
    with open(prefix + ".json") as f:
        exported = json.load(f)
    with open(os.path.join(scenes, scene + ".json")) as f:
        committed = json.load(f)
    if not numbers_close(exported, committed):
        failures.append(scene + ".json")
    for ext in (".obj", ".mtl"):
        with open(prefix + ext) as f, open(os.path.join(scenes, scene + ext)) as g:
            if f.read() != g.read():
                failures.append(scene + ext)
    print(scene, "checked")
if failures:
    sys.exit("stale scene descriptions (re-run Testing/Reference/make_reference.sh): " +
             ", ".join(failures))
