#!/usr/bin/env bash
# The GPU benchmark runs behind docs/performance.md: Cornell box, atrium and object field at
# 1920x1080, 128^3 and 256^3 voxels, full- and half-resolution tracing, 100 measured frames
# per sequence (each with plain VTK's frame in the same run), headless through EGL, with and
# without temporal reuse of the trace.
# Usage: run_gpu_benchmarks.sh BIN_DIR LIB_DIR OUTPUT_DIR [SCENES] [RESOLUTIONS] [TRACE_SCALES] [MACHINE] [REUSE]
set -eu
bin=$1; lib=$2; out=$3
scenes=${4:-"cornell atrium field"}; resolutions=${5:-"128 256"}; scales=${6:-"1 0.5"}
machine=${7:-h200}; reuses=${8:-"1 0"}
mkdir -p "$out"
export LD_PRELOAD="$lib/libVoxelGIGlewEGLShim.so"
for scene in $scenes; do
  for res in $resolutions; do
    for scale in $scales; do
      for reuse in $reuses; do
        name="$machine-$scene-1080p-$res-trace$scale-reuse$reuse"
        "$bin/VoxelGIBenchmark" --egl --scene "$scene" --size 1920x1080 --resolution "$res" \
          --trace-scale "$scale" --temporal-reuse "$reuse" --frames 100 --warmup 5 \
          --csv "$out/$name.csv" --json "$out/$name.json" 2>&1 | grep -v -E "WARN|^\s*$"
      done
    done
  done
done
tar czf "$out/benchmarks.tgz" -C "$out" $(cd "$out" && ls *.csv *.json)
rm -f "$out"/*.csv "$out"/*.json
