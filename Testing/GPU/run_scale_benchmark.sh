#!/usr/bin/env bash
# The scale benchmark: the scenes and sequences whose ratios to plain VTK are the goals of a
# GPU-resident scene (docs/performance.md), at 1920x1080 in VTK's default multisampled
# window, the pass's defaults, plain VTK's frame of the same scene in the same run, headless
# through EGL. Each JSON lists the settings it ran with.
#   sphere of N triangles, all moving and new data each frame, 128^3 and 256^3; at 128^3 also
#     through VTK's mappers (ComputeVoxelization=0)
#   atrium (81 actors), 256^3: all moving, one moving, light moving (each also while the window
#     renders interactively), camera only
#   field of 1000 actors, 128^3: all moving (also interactively), light moving, new data,
#     camera only
#   voxelization against triangles (compute and raster), 1e4 ... SWEEP_MAX, 128^3
# Usage: run_scale_benchmark.sh BIN_DIR LIB_DIR OUTPUT_DIR [MACHINE] [FRAMES] [SPHERE_TRIANGLES]
#                               [SWEEP_MAX]
set -eu
bin=$1; lib=$2; out=$3
machine=${4:-h200}; frames=${5:-40}; triangles=${6:-10000000}; sweep=${7:-30000000}
mkdir -p "$out"
export LD_PRELOAD="$lib/libVoxelGIGlewEGLShim.so"
run() {
  local name=$1 sequences=$2; shift 2
  "$bin/VoxelGIBenchmark" --egl --size 1920x1080 --frames "$frames" --warmup 5 \
    --sequences "$sequences" --json "$out/$machine-scale-$name.json" \
    --csv "$out/$machine-scale-$name.csv" "$@" 2>&1 | grep -v -E "WARN|ERR|^\s*$|wrote"
}
run field1000-128 orbit,light,all-moving,all-moving-interactive,new-data,plain,plain-new-data \
  --scene field --objects 999 --resolution 128
# The atrium's sequences in pairs, each pair in its own process with plain VTK's frame beside
# it: the lent GPUs' raster throughput has been seen to halve for a while (plain VTK's frame
# too), and a ratio is only meaningful between frames measured in the same state.
for q in orbit light one-moving all-moving; do
  pair=$([ "$q" = orbit ] && echo "orbit,plain" || echo "$q,$q-interactive,plain")
  run "atrium-256-$q" "$pair" --scene atrium --resolution 256
done
for res in 128 256; do
  run "sphere$triangles-$res" all-moving,new-data,plain,plain-new-data --scene sphere \
    --triangles "$triangles" --resolution "$res"
done
run "sphere$triangles-128-raster" all-moving,plain --scene sphere --triangles "$triangles" \
  --resolution 128 --set ComputeVoxelization=0
n=10000
while [ "$n" -le "$sweep" ]; do
  for path in compute raster; do
    value=$([ "$path" = compute ] && echo 1 || echo 0)
    run "sweep-$path-$n" all-moving,plain --scene sphere --triangles "$n" --resolution 128 \
      --set ComputeVoxelization="$value"
  done
  n=$((n * 10))
done
