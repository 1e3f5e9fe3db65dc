#!/usr/bin/env bash
# The scaling benchmark behind docs/performance.md: full-dynamic frames (every actor moves each
# frame) against the number of actors (a field of 1, 10, 100, 1000 actors) and against the
# number of triangles (one sphere of 1e3 ... 1e7 triangles), 1920x1080, 128^3 and 256^3
# voxels, plain VTK's frame of the same scene in the same run, headless through EGL.
# Usage: run_scaling_benchmark.sh BIN_DIR LIB_DIR OUTPUT_DIR [RESOLUTIONS] [MACHINE] [FRAMES]
# Plot: Testing/GPU/plot_scaling.py OUTPUT_DIR/MACHINE-scaling-*.json OUT.png
set -eu
bin=$1; lib=$2; out=$3
resolutions=${4:-"128 256"}; machine=${5:-h200}; frames=${6:-30}
mkdir -p "$out"
export LD_PRELOAD="$lib/libVoxelGIGlewEGLShim.so"
run() {
  local name=$1; shift
  "$bin/VoxelGIBenchmark" --egl --size 1920x1080 --frames "$frames" --warmup 5 \
    --sequences all-moving,plain --json "$out/$name.json" --csv "$out/$name.csv" "$@" 2>&1 |
    grep -v -E "WARN|^\s*$|wrote"
}
for res in $resolutions; do
  for actors in 1 10 100 1000; do
    run "$machine-scaling-actors$actors-$res" --scene field --objects $((actors - 1)) --resolution "$res"
  done
  for triangles in 1000 10000 100000 1000000 10000000; do
    run "$machine-scaling-triangles$triangles-$res" --scene sphere --triangles "$triangles" --resolution "$res"
  done
done
