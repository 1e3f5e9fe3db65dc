/**
 * The trace's resolution for an image (ConeTrace): TraceResolution of the image's, halved
 * while the traced pixels would exceed MaxTraceMegapixels (never below TraceResolution's
 * minimum, a quarter). Indirect light varies slowly over a surface, and above a megapixel a
 * quarter of the pixels, upsampled edge-aware by the composite, gives the same image against
 * the reference; below it the traced pixels grow too sparse for small features
 * (docs/performance.md, docs/reference.md). GL-free.
 */
#ifndef VoxelGITraceScale_h
#define VoxelGITraceScale_h

namespace voxelgi
{

/// The fraction of a `width` x `height` image's resolution to trace at, from the settings'
/// TraceResolution (`resolution`) and MaxTraceMegapixels (`maxMegapixels`, 0: no limit).
double TraceScale(double resolution, double maxMegapixels, int width, int height);

}

#endif
