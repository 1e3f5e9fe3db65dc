#!/bin/bash
# The error-against-time study on every reference scene: VoxelGIErrorStudy writes
# PREFIX-SCENE.csv for cornell, glossy, isosurface, glyphs, emissive, streamlines and the
# scenes nobody tuned the pass to (pointroom, lamproom, emitterroom, contacts,
# contactsheadlight, translucent). Extra arguments (--egl) go to the study program.
#
#   Testing/Reference/run_study.sh BIN_DIR PREFIX FRAMES [--egl]
set -euo pipefail
bin=$1; prefix=$2; frames=$3; shift 3
refs=$(cd "$(dirname "$0")/../Data/Reference" && pwd)
for scene in cornell glossy isosurface glyphs emissive streamlines pointroom lamproom emitterroom \
  contacts contactsheadlight translucent; do
  "$bin/VoxelGIErrorStudy" "$@" "$scene" "$refs/$scene.pfm" "$prefix-$scene.csv" "$frames"
done
