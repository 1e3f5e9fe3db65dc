#!/usr/bin/env bash
# The anti-aliasing benchmark: what a frame costs over plain VTK now that VTK draws its own
# multisampled image and GI is blended into it (docs/performance.md), at 1920x1080, the
# pass's defaults, plain VTK's frame of the same scene in the same run, headless through EGL;
# in VTK's default 8x window and in a window without multisampling. Each JSON lists the
# settings it ran with. Each GI sequence runs in its own process with plain VTK's frame
# measured right after it: the H200's clocks follow the load, and plain VTK's frame of the
# same view measured after unchanged frames took twice as long as after camera moves.
#   Cornell box 128^3 and atrium 256^3: nothing changes (static), camera only (orbit)
# Usage: run_antialiasing_benchmark.sh BIN_DIR LIB_DIR OUTPUT_DIR [MACHINE] [FRAMES]
set -eu
bin=$1; lib=$2; out=$3
machine=${4:-h200}; frames=${5:-100}
mkdir -p "$out"
export LD_PRELOAD="$lib/libVoxelGIGlewEGLShim.so"
for samples in 8 0; do
  for scene in cornell:128 atrium:256; do
    for sequence in static orbit; do
      name="$machine-aa-${scene%%:*}-1080p-${scene##*:}-msaa$samples-$sequence"
      "$bin/VoxelGIBenchmark" --egl --size 1920x1080 --frames "$frames" --warmup 10 \
        --scene "${scene%%:*}" --resolution "${scene##*:}" --multisamples "$samples" \
        --sequences "$sequence,plain" --json "$out/$name.json" --csv "$out/$name.csv" 2>&1 |
        grep -v -E "WARN|ERR|^\s*$|wrote"
    done
  done
done
