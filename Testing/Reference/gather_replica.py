"""A replica of the pixels' diffuse gather in numpy, to study how the cones respond to what the
voxels hold (docs/reference.md, "Where a compact source is counted twice"):

    PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
        Testing/Reference/gather_replica.py SCENE X Y Z NX NY NZ [independent] [own-step]

renders the built-in SCENE (vtkVoxelGIScenes) with `Bounces` 0 and no tail, reads the pass's
radiance volume back, and gathers at the world point (X, Y, Z) with unit normal (NX, NY, NZ)
as the pass does: the six directional mipmaps built as voxel_mipmap.comp builds them (the lit
side of each voxel left out: every voxel sends its light every way) and sixteen cones turned
four ways traced as cone_tracing.glsl traces them, without the read at the scene's bounds. It
prints the replica's gather beside the pass's own at that pixel (its composite over the
albedo), so that a replica that no longer matches the shaders shows at once. The mipmaps are
built for surfaces alone (a medium's independent share is left out), over the columns inside
the scene's bounds (taken as the occupied voxels' bounds). `independent` composites the mip
levels above the first as independent layers; `own-step` corrects a sample's opacity for its
own diameter's step instead of the step it arrived by: what the pass did before the small
emitter's excess was found. Both change what the replica traces, not the pass.
"""
import sys

import numpy as np
from scipy.ndimage import map_coordinates
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow

from voxelgi import vtkVoxelGIPass, vtkVoxelGIScenes

TAN_HALF = np.tan(np.radians(30.0))  # DiffuseConeAperture 60
STEP = 0.75                          # ConeStepFactor
START_OFFSET = 1.5                   # ConeStartOffset


def build(radiance, direction, correlated, lo, hi):
    """The directional levels (texels of 2, 4, ... voxels) for travel along +x, -x, +y, ...;
    `lo`, `hi`: the scene's bounds in voxels (z, y, x)."""
    axis = (2, 2, 1, 1, 0, 0)[direction]  # arrays are indexed z, y, x
    levels, source = [], radiance
    while source.shape[0] >= 2:
        even = np.take(source, np.arange(0, source.shape[0], 2), axis=axis)
        odd = np.take(source, np.arange(1, source.shape[0], 2), axis=axis)
        front, back = (even, odd) if direction % 2 == 0 else (odd, even)
        if correlated and levels:
            covered = np.maximum(front[..., 3:], back[..., 3:])
            share = np.where(back[..., 3:] > 0.0, (covered - front[..., 3:]) /
                             np.maximum(back[..., 3:], 1e-9), 0.0)
            line = np.concatenate([front[..., :3] + share * back[..., :3], covered], axis=-1)
        else:
            line = front + (1.0 - front[..., 3:]) * back
        # columns wholly outside the scene's bounds are left out of the average
        texel = 2.0 ** len(levels)
        inside = np.ones(line.shape[:3], bool)
        for a in range(3):
            span = 2.0 * texel if a == axis else texel
            start = np.arange(line.shape[a]) * span
            shape = [1, 1, 1]
            shape[a] = -1
            inside &= ((start < hi[a]) & (start + span > lo[a])).reshape(shape)
        line = line * inside[..., None]
        count = inside[..., None].astype(np.float64)
        for other in (a for a in (0, 1, 2) if a != axis):
            n = line.shape[other]
            line = (np.take(line, np.arange(0, n, 2), axis=other) +
                    np.take(line, np.arange(1, n, 2), axis=other))
            count = (np.take(count, np.arange(0, n, 2), axis=other) +
                     np.take(count, np.arange(1, n, 2), axis=other))
        line = np.where(count > 0.0, line / np.maximum(count, 1.0), 0.0)
        levels.append(line)
        source = line
    return levels


def trilinear(volume, p, texel):
    q = p / texel - 0.5
    return np.array([map_coordinates(volume[..., c], [[q[2]], [q[1]], [q[0]]], order=1,
                                     mode="nearest")[0] for c in range(4)])


class Gather:
    def __init__(self, radiance, correlated=True, arrival=True):
        self.radiance = radiance
        occupied = np.argwhere(radiance[..., 3] > 0.0)
        lo, hi = occupied.min(axis=0), occupied.max(axis=0) + 1
        self.mips = [build(radiance, d, correlated, lo, hi) for d in range(6)]
        self.arrival = arrival

    def sample(self, p, diameter, d):
        level = max(np.log2(max(diameter, 1.0)), 0.0)
        lod = max(level - 1.0, 0.0)
        k = int(np.floor(lod))
        s = np.zeros(4)
        for axis in range(3):
            levels = self.mips[2 * axis + (0 if d[axis] >= 0.0 else 1)]
            k0, k1 = min(k, len(levels) - 1), min(k + 1, len(levels) - 1)
            f = lod - k
            s += d[axis] ** 2 * ((1.0 - f) * trilinear(levels[k0], p, 2.0 ** (k0 + 1)) +
                                 f * trilinear(levels[k1], p, 2.0 ** (k1 + 1)))
        return s if level >= 1.0 else (1.0 - level) * trilinear(self.radiance, p, 1.0) + level * s

    def cone(self, origin, d, surface, n):
        acc, t, arrived = np.zeros(4), 1.0, None
        res = self.radiance.shape[0]
        while acc[3] < 0.99:
            p = origin + d * t
            if np.any(p < 0.0) or np.any(p > res):
                break
            height = np.dot(p - surface, n)
            if height < 2.5:  # the footprint's guard (voxelConeFootprint)
                p, height = p + n * (2.5 - height), 2.5
            diameter = max(min(2.0 * TAN_HALF * t, 2.0 ** np.floor(np.log2((height - 1.0) / 1.5))),
                           1.0)
            s = self.sample(p, diameter, d)
            exponent = (STEP if not self.arrival or arrived is None
                        else min(arrived / diameter, STEP))
            a = 1.0 - np.clip(1.0 - s[3], 0.0, 1.0) ** exponent
            acc[:3] += (1.0 - acc[3]) * (s[:3] * (a / s[3]) if s[3] > 1e-4 else 0.0)
            acc[3] += (1.0 - acc[3]) * a
            arrived = diameter * STEP
            t += arrived
        return acc

    def at(self, p, n, count=16):
        s = 1.0 if n[2] >= 0.0 else -1.0
        a = -1.0 / (s + n[2])
        c = n[0] * n[1] * a
        t0 = np.array([1.0 + s * n[0] * n[0] * a, s * c, -s * n[0]])
        b0 = np.array([c, s + n[1] * n[1] * a, -n[1]])
        golden, total = np.pi * (3.0 - np.sqrt(5.0)), np.zeros(3)
        for turn in range(4):
            angle = 0.5 * np.pi * turn
            t, b = np.cos(angle) * t0 + np.sin(angle) * b0, np.cos(angle) * b0 - np.sin(angle) * t0
            for i in range(count):
                polar = np.arcsin(np.sqrt((i + 0.5) / count))
                d = (np.sin(polar) * (np.cos(golden * i) * t + np.sin(golden * i) * b) +
                     np.cos(polar) * n)
                total += self.cone(p + n * START_OFFSET, d / np.linalg.norm(d), p, n)[:3]
        return total / (4 * count)


def replica_and_pass(scene, world, normal, options=()):
    """The replica's gather at `world` (normal `normal`) in the built-in `scene`, and the pass's
    indirect light there (albedo x gather: 3 x 3 pixels' mean; None off the image)."""
    normal = normal / np.linalg.norm(normal)
    renderer = vtkRenderer()
    if not vtkVoxelGIScenes.AddScene(renderer, scene):
        raise ValueError("unknown scene " + scene)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(200, 200)
    gi = vtkVoxelGIPass()
    gi.SetSoftwareProfile(0)
    gi.SetBounces(0)
    gi.SetBounceTail(False)
    renderer.SetPass(gi)
    window.Render()
    image = vtkImageData()
    if not gi.GetVoxelVolume(vtkVoxelGIPass.VOLUME_RADIANCE, image):
        raise RuntimeError("GI did not run")
    dims, h = image.GetDimensions(), image.GetSpacing()[0]
    radiance = vtk_to_numpy(image.GetPointData().GetArray(0)).reshape(dims[2], dims[1], dims[0], 4)
    corner = np.array(image.GetOrigin()) - 0.5 * h
    gather = Gather(radiance.astype(np.float64), "independent" not in options,
                    "own-step" not in options)
    replica = gather.at((world - corner) / h, normal)
    pixels = vtkFloatArray()
    gi.GetFloatImage(vtkVoxelGIPass.IMAGE_INDIRECT, pixels)
    renderer.SetWorldPoint(*world, 1.0)
    renderer.WorldToDisplay()
    x, y = (int(round(v - 0.5)) for v in renderer.GetDisplayPoint()[:2])
    if not (1 <= x < 199 and 1 <= y < 199):
        return replica, None
    indirect = vtk_to_numpy(pixels).reshape(200, 200, 4)[y - 1:y + 2, x - 1:x + 2, :3]
    return replica, indirect.reshape(-1, 3).mean(axis=0)


def main():
    world, normal = np.array(sys.argv[2:5], float), np.array(sys.argv[5:8], float)
    replica, indirect = replica_and_pass(sys.argv[1], world, normal, sys.argv[8:])
    line = "replica %s" % np.round(replica, 4)
    if indirect is not None:
        line += "; the pass's indirect light there: %s (albedo x gather)" % np.round(indirect, 4)
    print(line)


if __name__ == "__main__":
    main()
