#include "TraceScale.h"

namespace voxelgi
{

double TraceScale(double resolution, double maxMegapixels, int width, int height)
{
  constexpr double Finest = 0.25; // TraceResolution's minimum: the composite's reach is set for it
  double scale = resolution;
  const double pixels = static_cast<double>(width) * static_cast<double>(height);
  while (maxMegapixels > 0.0 && 0.5 * scale >= Finest &&
    pixels * scale * scale > maxMegapixels * 1e6)
  {
    scale *= 0.5;
  }
  return scale;
}

}
