#!/usr/bin/env bash
# The GPU benchmark runs behind docs/performance.md: Cornell box and atrium at 1920x1080,
# 128^3 and 256^3 voxels, 100 measured frames per sequence, headless through EGL.
# Usage: run_gpu_benchmarks.sh BIN_DIR LIB_DIR OUTPUT_DIR
set -eu
bin=$1; lib=$2; out=$3
mkdir -p "$out"
export LD_PRELOAD="$lib/libVoxelGIGlewEGLShim.so"
for scene in cornell atrium; do
  for res in 128 256; do
    "$bin/VoxelGIBenchmark" --egl --scene "$scene" --size 1920x1080 --resolution "$res" \
      --frames 100 --warmup 5 --csv "$out/h100-$scene-1080p-$res.csv" \
      --json "$out/h100-$scene-1080p-$res.json" --image "$out/h100-$scene-1080p-$res.png" 2>&1 |
      grep -v -E "WARN|^\s*$"
  done
done
