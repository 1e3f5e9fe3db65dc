#!/bin/bash
# Renders the path-traced reference of a scene description (vtkVoxelGISceneFile) with Blender
# Cycles: PREFIX.pfm, PREFIX.png and PREFIX.txt. The .txt file records the sample count, the
# render time and the remaining noise, estimated from two independent renders of a quarter of
# the samples (RMSE between them / sqrt(2) is the noise of one; a four times larger sample
# count halves it).
#
#   Testing/Reference/render_reference.sh SCENE.json PREFIX [SAMPLES] [BOUNCES]
#
# BOUNCES (default 8) caps the paths' bounces (render_cycles.py).
set -euo pipefail
scene=$1
prefix=$2
samples=${3:-4096}
bounces=${4:-8}
here=$(cd "$(dirname "$0")" && pwd)

render() { # prefix samples seed
  blender -b -P "$here/render_cycles.py" -- "$scene" "$1" "$2" "$3" "$bounces" > /dev/null
}
start=$(date +%s)
render "$prefix" "$samples" 1
seconds=$(( $(date +%s) - start ))
noise=$(mktemp -d)
trap 'rm -rf "$noise"' EXIT
render "$noise/a" $((samples / 4)) 2
render "$noise/b" $((samples / 4)) 3
PYTHONPATH=$here /usr/bin/python3 - "$noise/a.pfm" "$noise/b.pfm" "$prefix.pfm" "$samples" "$seconds" \
  > "$prefix.txt" <<'PY'
import sys
import numpy as np
from float_images import read_pfm

a, b, ref = (read_pfm(p) for p in sys.argv[1:4])
samples, seconds = sys.argv[4:6]
quarter = np.sqrt(np.mean((a - b) ** 2)) / np.sqrt(2.0)
print("samples per pixel: %s" % samples)
print("render time: %s s (Blender Cycles, CPU)" % seconds)
print("mean pixel value: %.4f" % ref.mean())
print("noise, RMSE: %.4f (two renders of %d samples differ by %.4f)"
      % (quarter / 2.0, int(samples) // 4, quarter * np.sqrt(2.0)))
PY
cat "$prefix.txt"
