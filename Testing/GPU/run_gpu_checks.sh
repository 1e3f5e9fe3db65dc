#!/usr/bin/env bash
# Runs the C++ tests and the demo headless through EGL on a GPU machine (no X server).
# Usage: run_gpu_checks.sh BIN_DIR LIB_DIR OUTPUT_DIR [--write-baselines]
# BIN_DIR holds vtkRenderingVoxelGICxxTests and VoxelGIDemo, LIB_DIR the GLEW shim.
# The images are compared with the NVIDIA baselines (Testing/Data/Baseline/NVIDIA): the
# strict comparison is tuned to one renderer's rasterization, and Mesa's baselines differ
# from an NVIDIA GPU's at edges (0.05-1.7 % of the pixels by more than 12 levels). With
# --write-baselines each test writes its image into OUTPUT_DIR/baselines instead, to be
# looked at and committed there.
set -u
bin=$1; lib=$2; out=$3; write=${4:-}
mkdir -p "$out/images" "$out/baselines"
export VOXELGI_EGL=1 LD_PRELOAD="$lib/libVoxelGIGlewEGLShim.so"
data="$(cd "$(dirname "$0")/../Data/Baseline" && pwd)"
status=0
for t in TestVoxelConservative TestVoxelAverage TestVoxelDynamic TestGINumerics \
         TestVoxelAlbedoCornell TestVoxelScalarColors TestVoxelTexture TestGIDisabled \
         TestGICornell TestGIAmbientOcclusionView TestGIIndirectView TestGIEmissiveOnly \
         TestGIGlossyFloor TestGISpotLight TestGIHeadlight; do
  args=()
  if [ -f "$data/$t.png" ]; then
    if [ "$write" = --write-baselines ]; then
      args=(-V "$out/baselines/none/$t.png" -T "$out/baselines")
    elif [ -f "$data/NVIDIA/$t.png" ]; then
      args=(-V "$data/NVIDIA/$t.png" -T "$out/images")
    else
      echo "$t: no NVIDIA baseline"; status=1; continue
    fi
  fi
  "$bin/vtkRenderingVoxelGICxxTests" "$t" "${args[@]}" > "$out/$t.log" 2>&1
  rc=$?
  if [ "$write" = --write-baselines ] && [ ${#args[@]} -gt 0 ]; then
    echo "$t: image written (its other checks: see $t.log)"; continue
  fi
  echo "$t: exit $rc"
  grep -E "strict image|triangles|count|furnace|plane|floor|indirect|bytes differ|radiance|quadrant|voxels|conservative" "$out/$t.log" | sed 's/^/    /' | head -12
  [ $rc -eq 0 ] || status=1
done
"$bin/VoxelGIDemo" "$out/images/demo" --egl > "$out/demo.log" 2>&1
echo "demo: exit $?"
grep -E "Stage|Grid|Memory" "$out/demo.log" | sed 's/^/    /'
exit $status
