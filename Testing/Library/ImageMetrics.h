// Error metrics between a rendered image and a reference, both linear RGB (three floats per
// pixel, rows bottom to top as VTK reads them back). Used to report our error against
// path-traced references.
#ifndef VoxelGIImageMetrics_h
#define VoxelGIImageMetrics_h

#include "vtkTestingVoxelGIModule.h" // for export macro

#include <string>
#include <vector>

namespace voxelgi
{
namespace metrics
{
struct Image
{
  int Width = 0;
  int Height = 0;
  std::vector<float> Rgb; // Width * Height * 3, linear
};

// Reads a portable float map ("PF", little endian, rows bottom to top), the format of the
// path-traced references. False when the file is missing or not such a map.
VTKTESTINGVOXELGI_EXPORT bool ReadPfm(const std::string& path, Image& image);

// Writes `image` as such a map (little endian, as the machines we run on). False on failure.
VTKTESTINGVOXELGI_EXPORT bool WritePfm(const std::string& path, const Image& image);

// The RGB part of an RGBA float image (as VTK reads frame buffers back).
VTKTESTINGVOXELGI_EXPORT Image FromRgba(const float* rgba, int width, int height);

// Root mean squared error over all pixels and channels.
VTKTESTINGVOXELGI_EXPORT double Rmse(const Image& test, const Image& reference);

// Relative MSE: mean of (test - ref)^2 / (ref^2 + 0.01) over pixels and channels, so that
// dark regions weigh as much as bright ones.
VTKTESTINGVOXELGI_EXPORT double RelMse(const Image& test, const Image& reference);

// Mean SSIM (Wang et al. 2004) of the luminance (Rec. 709 weights) of the images clamped to
// [0, 1], with an 11 x 11 Gaussian window (sigma 1.5), C1 = 0.01^2, C2 = 0.03^2.
VTKTESTINGVOXELGI_EXPORT double Ssim(const Image& test, const Image& reference);

// Mean LDR-FLIP (Andersson et al. 2020, "FLIP: A Difference Evaluator for Alternating Images"),
// on the images clamped to [0, 1], for an observer at `pixelsPerDegree` (67 = 0.7 m from a
// 0.7 m wide 3840-pixel display, the paper's default). 0 = identical, 1 = maximal.
VTKTESTINGVOXELGI_EXPORT double Flip(
  const Image& test, const Image& reference, double pixelsPerDegree = 67.0);

// All four metrics of one image against a reference.
struct Errors
{
  double Rmse = 0.0;
  double RelMse = 0.0;
  double Ssim = 0.0;
  double Flip = 0.0;
};
VTKTESTINGVOXELGI_EXPORT Errors Compare(const Image& test, const Image& reference);
}
}

#endif
