#!/bin/bash
# Error against run time for a scene of your own, in one command: renders the path-traced
# reference of a scene description (written from any renderer by vtkVoxelGISceneFile::Write),
# runs the error study on it (plain VTK, SSAO, the pass at its defaults and with each setting
# varied) and writes the table, the Pareto plots and the images side by side:
#   OUT_DIR/NAME.{pfm,png,txt}        the reference (kept and reused when it exists)
#   OUT_DIR/study-NAME.csv            the study, and study-NAME-{plain,ssao,defaults}.pfm
#   OUT_DIR/study-NAME.{png,md}       Pareto plots and table
#   OUT_DIR/comparison.png            reference, plain VTK, SSAO, GI, |GI - reference|
#
#   Testing/Reference/study_scene.sh SCENE.json OUT_DIR [SAMPLES [FRAMES]] [--egl]
#
# SAMPLES: Cycles samples per pixel (default 1024); FRAMES: timed frames per configuration
# (default 5). VOXELGI_MACHINE names the machine in the plots. Needs blender
# (apt-get install blender) and the build in ./build.
set -euo pipefail
egl=()
args=()
for a in "$@"; do
  if [ "$a" = --egl ]; then egl=(--egl); else args+=("$a"); fi
done
scene=$(realpath "${args[0]}")
out=${args[1]}
samples=${args[2]:-1024}
frames=${args[3]:-5}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
name=$(basename "$scene" .json)
mkdir -p "$out"
if [ ! -f "$out/$name.pfm" ]; then
  "$here/render_reference.sh" "$scene" "$out/$name" "$samples"
fi
run=()
[ ${#egl[@]} -gt 0 ] || [ -n "${DISPLAY:-}" ] || run=(xvfb-run -a -s "-screen 0 1280x1024x24 -noreset")
"${run[@]}" "$root/build/bin/VoxelGIErrorStudy" "${egl[@]}" "$scene" "$out/$name.pfm" \
  "$out/study-$name.csv" "$frames"
machine=${VOXELGI_MACHINE:-$(grep -m1 "model name" /proc/cpuinfo | cut -d: -f2 | xargs)}
[ ${#egl[@]} -gt 0 ] && machine="$machine, EGL" || machine="$machine, Mesa llvmpipe"
/usr/bin/python3 "$here/plot_study.py" "$out/study-$name.csv" "$out/study-$name.png" \
  "$out/study-$name.md" "$machine" "$name"
/usr/bin/python3 "$here/compare_images.py" "$out/comparison.png" "$out/study" "$name" --references "$out"
echo "table: $out/study-$name.md, plots: $out/study-$name.png, images: $out/comparison.png"
