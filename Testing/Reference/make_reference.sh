#!/bin/bash
# Exports one built-in scene and renders its path-traced reference with Blender Cycles:
#   Testing/Data/Scenes/SCENE.{obj,mtl,json}, Testing/Data/Reference/SCENE.{pfm,png,txt}.
#
#   Testing/Reference/make_reference.sh SCENE [SAMPLES] [BOUNCES]   (from the source tree, after .ci/setup)
#
# With BOUNCES the paths stop after that many bounces and the reference is written as
# Testing/Data/Reference/SCENE-bBOUNCES.{pfm,png,txt} (TestGIReference's orders).
set -euo pipefail
scene=$1
samples=${2:-4096}
bounces=${3:-}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
PYTHONPATH=$root/build/lib/python3/dist-packages xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" /usr/bin/python3 \
  "$here/export_scene.py" "$scene" "$root/Testing/Data/Scenes/$scene"
"$here/render_reference.sh" "$root/Testing/Data/Scenes/$scene.json" \
  "$root/Testing/Data/Reference/$scene${bounces:+-b$bounces}" "$samples" "${bounces:-8}"
