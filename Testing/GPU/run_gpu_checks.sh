#!/usr/bin/env bash
# Runs the C++ tests and the demo headless through EGL on a GPU machine (no X server).
# Usage: run_gpu_checks.sh BIN_DIR LIB_DIR OUTPUT_DIR
# BIN_DIR holds vtkRenderingVoxelGICxxTests and VoxelGIDemo, LIB_DIR the GLEW shim.
set -u
bin=$1; lib=$2; out=$3
mkdir -p "$out/images"
export VOXELGI_EGL=1 LD_PRELOAD="$lib/libVoxelGIGlewEGLShim.so"
baselines="$(cd "$(dirname "$0")/../Data/Baseline" && pwd)"
status=0
for t in TestVoxelConservative TestVoxelAverage TestVoxelDynamic TestGINumerics \
         TestVoxelAlbedoCornell TestVoxelScalarColors TestVoxelTexture TestGIDisabled \
         TestGICornell TestGIAmbientOcclusionView TestGIIndirectView TestGIEmissiveOnly \
         TestGIGlossyFloor TestGISpotLight TestGIHeadlight; do
  args=()
  [ -f "$baselines/$t.png" ] && args=(-V "$baselines/$t.png" -T "$out/images")
  "$bin/vtkRenderingVoxelGICxxTests" "$t" "${args[@]}" > "$out/$t.log" 2>&1
  rc=$?
  echo "$t: exit $rc"
  grep -E "strict image|triangles|count|furnace|plane|floor|indirect|bytes differ|radiance|quadrant|voxels|conservative" "$out/$t.log" | sed 's/^/    /' | head -12
  [ $rc -eq 0 ] || status=1
done
"$bin/VoxelGIDemo" "$out/images/demo" --egl > "$out/demo.log" 2>&1
echo "demo: exit $?"
grep -E "Stage|Grid|Memory" "$out/demo.log" | sed 's/^/    /'
exit $status
