#!/usr/bin/env bash
# Two builds of the library against each other in one run, on the same GPU and in alternating
# processes (the GPU's clocks follow the load, and plain VTK's frame moved by a factor of two
# between processes of one call on an H100): a camera move of the Cornell box 128^3 and the
# atrium 256^3 at 1920x1080, in VTK's default 8x window and without multisampling, the
# pass's defaults, plain VTK's frame in the same process. One line per run: the GI frame,
# plain VTK's and every stage that ran.
# Usage: run_ab_benchmark.sh BIN_DIR LIB_DIR OLD_LIB_DIR OUTPUT_DIR [ROUNDS] [FRAMES]
# BIN_DIR holds VoxelGIBenchmark, LIB_DIR the GLEW shim and the new library, OLD_LIB_DIR the
# other libvtkRenderingVoxelGI.so.
set -u
bin=$1; lib=$2; old=$3; out=$4
rounds=${5:-2}; frames=${6:-40}
mkdir -p "$out"
for round in $(seq "$rounds"); do
  for build in old new; do
    path=$lib
    [ "$build" = old ] && path=$old:$lib
    for samples in 8 0; do
      for scene in cornell:128 atrium:256; do
        name="$build-${scene%%:*}-msaa$samples-$round"
        LD_LIBRARY_PATH=$path LD_PRELOAD="$lib/libVoxelGIGlewEGLShim.so" \
          "$bin/VoxelGIBenchmark" --egl --size 1920x1080 --frames "$frames" --warmup 10 \
          --scene "${scene%%:*}" --resolution "${scene##*:}" --multisamples "$samples" \
          --sequences orbit,plain --json "$out/$name.json" > "$out/$name.log" 2>&1
        python3 - "$out/$name.json" "$name" <<'PY'
import json
import sys
try:
    median = json.load(open(sys.argv[1]))['median_ms']
except (OSError, ValueError, KeyError):
    sys.exit(print(sys.argv[2], 'no result'))
gi, plain = median.get('orbit', {}), median.get('plain', {})
stages = ' '.join('%s=%.3f' % (k, v) for k, v in gi.items() if v and k not in ('frame', 'frame_mean'))
print('%s camera move %.2f ms, plain VTK %.2f ms: %s' % (sys.argv[2], gi.get('frame', 0), plain.get('frame', 0), stages))
PY
      done
    done
  done
done
