#!/usr/bin/env python3
"""Sums the lines libVoxelGIGLCallProfiler.so wrote per kind of GL work: each call's name, the
words that tell its program apart (gl_call_profiler.c), its draw framebuffer and viewport,
as milliseconds of GPU time per frame, largest first, and the CPU time spent in glFinish.
Usage: gl_call_profile.py PROFILE FRAMES [LINES]   (FRAMES: the frames the program rendered)"""
import collections
import sys


def main():
    path, frames = sys.argv[1], float(sys.argv[2])
    lines = int(sys.argv[3]) if len(sys.argv) > 3 else 20
    words = {}
    total = collections.defaultdict(float)
    calls = collections.Counter()
    finish = []
    with open(path) as profile:
        for line in profile:
            f = line.split()
            if not f:
                continue
            if f[0] == 'PROGRAM':
                words[int(f[1])] = ' '.join(f[3:]) or '-'
            elif f[0] == 'FINISH':
                finish.append(float(f[1]))
            elif f[0] == 'CALL':
                name, program, draw, width, height = f[1], int(f[2]), f[3], f[5], f[6]
                key = (name, program, words.get(program, '-'), draw, width + 'x' + height)
                total[key] += float(f[8])
                calls[key] += 1
    print('glFinish: %d calls, %.2f ms a frame' % (len(finish), sum(finish) / 1e3 / frames))
    print('%9s %7s  %s' % ('ms/frame', 'calls', 'call, program, its words, framebuffer, viewport'))
    for key, us in sorted(total.items(), key=lambda kv: -kv[1])[:lines]:
        print('%9.3f %7.1f  %s %d [%s] fb %s %s' % (us / 1e3 / frames, calls[key] / frames, *key))
    print('%9.3f          all timed calls' % (sum(total.values()) / 1e3 / frames))


if __name__ == '__main__':
    main()
