#!/usr/bin/env bash
# The volume benchmark: a 256^3 volume (VTK's wavelet, GPU ray cast) over a floor beside a
# sphere, at 1920x1080 in VTK's default multisampled window, the pass's defaults, headless
# through EGL, plain VTK's frame of the same scene in the same run: a camera orbit (the volume
# is not resampled), a transfer function that changes every frame (resampled every frame),
# and an unchanged frame; at 128^3 and 256^3 voxels.
# Usage: run_volume_benchmark.sh BIN_DIR LIB_DIR OUTPUT_DIR [MACHINE] [FRAMES]
set -eu
bin=$1; lib=$2; out=$3
machine=${4:-h200}; frames=${5:-40}
mkdir -p "$out"
export LD_PRELOAD="$lib/libVoxelGIGlewEGLShim.so"
for res in 128 256; do
  "$bin/VoxelGIBenchmark" --egl --size 1920x1080 --frames "$frames" --warmup 5 \
    --scene volume --resolution "$res" --sequences static,orbit,transfer-function,plain \
    --json "$out/$machine-volume-$res.json" --csv "$out/$machine-volume-$res.csv" 2>&1 |
    grep -v -E "WARN|ERR|^\s*$|wrote"
done
