#include "ImageMetrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <functional>
#include <stdexcept>

namespace voxelgi
{
namespace metrics
{
namespace
{
constexpr double Pi = 3.14159265358979323846;
using Plane = std::vector<double>; // one channel, Width * Height
using Vec3 = std::array<double, 3>;

void CheckSizes(const Image& a, const Image& b)
{
  const std::size_t n = static_cast<std::size_t>(a.Width) * a.Height * 3;
  if (a.Width != b.Width || a.Height != b.Height || a.Rgb.size() != n || b.Rgb.size() != n ||
    n == 0)
  {
    throw std::invalid_argument("images differ in size or are empty");
  }
}

double Clamp01(double v)
{
  return std::min(1.0, std::max(0.0, v));
}

// Separable convolution with clamp-to-edge borders: `kx` along rows, then `ky` along columns.
// Both kernels have odd length, centred.
Plane Convolve(const Plane& in, int w, int h, const std::vector<double>& kx,
  const std::vector<double>& ky)
{
  Plane tmp(in.size()), out(in.size());
  const int rx = static_cast<int>(kx.size() / 2), ry = static_cast<int>(ky.size() / 2);
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      double s = 0.0;
      for (int k = -rx; k <= rx; ++k)
      {
        s += kx[k + rx] * in[y * w + std::min(w - 1, std::max(0, x + k))];
      }
      tmp[y * w + x] = s;
    }
  }
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      double s = 0.0;
      for (int k = -ry; k <= ry; ++k)
      {
        s += ky[k + ry] * tmp[std::min(h - 1, std::max(0, y + k)) * w + x];
      }
      out[y * w + x] = s;
    }
  }
  return out;
}

// 1D kernel of `radius` built from f(offset in pixels).
std::vector<double> Kernel(int radius, const std::function<double(double)>& f)
{
  std::vector<double> k(2 * radius + 1);
  for (int i = -radius; i <= radius; ++i)
  {
    k[i + radius] = f(i);
  }
  return k;
}

void NormalizeSum(std::vector<double>& k)
{
  double s = 0.0;
  for (double v : k)
  {
    s += v;
  }
  for (double& v : k)
  {
    v /= s;
  }
}

// FLIP's feature kernels: positive and negative weights each sum to +1 and -1.
void NormalizeSigned(std::vector<double>& k)
{
  double pos = 0.0, neg = 0.0;
  for (double v : k)
  {
    (v > 0.0 ? pos : neg) += v;
  }
  for (double& v : k)
  {
    v = v > 0.0 ? v / pos : (v < 0.0 ? -v / neg : 0.0);
  }
}

double Luminance(const Image& im, std::size_t i)
{
  return 0.2126 * Clamp01(im.Rgb[3 * i]) + 0.7152 * Clamp01(im.Rgb[3 * i + 1]) +
    0.0722 * Clamp01(im.Rgb[3 * i + 2]);
}

// Colour spaces of FLIP (sRGB primaries, D65 white).
const Vec3 WhiteXyz = { 0.950428545, 1.0, 1.088900371 };

Vec3 LinearRgbToXyz(const Vec3& c)
{
  return { 0.4124564 * c[0] + 0.3575761 * c[1] + 0.1804375 * c[2],
    0.2126729 * c[0] + 0.7151522 * c[1] + 0.0721750 * c[2],
    0.0193339 * c[0] + 0.1191920 * c[1] + 0.9503041 * c[2] };
}

Vec3 XyzToLinearRgb(const Vec3& c)
{
  return { 3.2404542 * c[0] - 1.5371385 * c[1] - 0.4985314 * c[2],
    -0.9692660 * c[0] + 1.8760108 * c[1] + 0.0415560 * c[2],
    0.0556434 * c[0] - 0.2040259 * c[1] + 1.0572252 * c[2] };
}

// YCxCz: the linearized CIELAB opponent space in which FLIP applies its contrast sensitivity.
Vec3 XyzToYcxcz(const Vec3& c)
{
  const double x = c[0] / WhiteXyz[0], y = c[1] / WhiteXyz[1], z = c[2] / WhiteXyz[2];
  return { 116.0 * y - 16.0, 500.0 * (x - y), 200.0 * (y - z) };
}

Vec3 YcxczToXyz(const Vec3& c)
{
  const double y = (c[0] + 16.0) / 116.0;
  return { (c[1] / 500.0 + y) * WhiteXyz[0], y * WhiteXyz[1], (y - c[2] / 200.0) * WhiteXyz[2] };
}

// CIELAB with the Hunt effect (chroma scaled by lightness), as FLIP compares colours.
Vec3 HuntLab(const Vec3& rgb)
{
  const Vec3 xyz = LinearRgbToXyz(rgb);
  auto f = [](double t) {
    const double d = 6.0 / 29.0;
    return t > d * d * d ? std::cbrt(t) : t / (3.0 * d * d) + 4.0 / 29.0;
  };
  const double fx = f(xyz[0] / WhiteXyz[0]), fy = f(xyz[1] / WhiteXyz[1]),
               fz = f(xyz[2] / WhiteXyz[2]);
  const double l = 116.0 * fy - 16.0;
  return { l, 0.01 * l * 500.0 * (fx - fy), 0.01 * l * 200.0 * (fy - fz) };
}

double HyAb(const Vec3& a, const Vec3& b)
{
  return std::abs(a[0] - b[0]) + std::hypot(a[1] - b[1], a[2] - b[2]);
}

// The colour pipeline: YCxCz planes of an image, filtered by FLIP's contrast sensitivity
// functions, back to linear RGB clamped to [0, 1], to Hunt-adjusted CIELAB.
std::vector<Vec3> FilteredHuntLab(const Image& im, double ppd)
{
  const int w = im.Width, h = im.Height;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  std::array<Plane, 3> ycc;
  for (auto& p : ycc)
  {
    p.resize(n);
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    const Vec3 c = XyzToYcxcz(LinearRgbToXyz(
      { Clamp01(im.Rgb[3 * i]), Clamp01(im.Rgb[3 * i + 1]), Clamp01(im.Rgb[3 * i + 2]) }));
    for (int k = 0; k < 3; ++k)
    {
      ycc[k][i] = c[k];
    }
  }
  // Each channel's CSF is a1 sqrt(pi/b1) exp(-pi^2 r^2/b1) + a2 sqrt(pi/b2) exp(-pi^2 r^2/b2),
  // r in degrees; each Gaussian is separable, the kernel is normalized as a whole.
  const double a1[3] = { 1.0, 1.0, 34.1 }, b1[3] = { 0.0047, 0.0053, 0.04 };
  const double a2[3] = { 0.0, 0.0, 13.5 }, b2[3] = { 1.0e-5, 1.0e-5, 0.025 };
  const double maxB = 0.04;
  const int radius = static_cast<int>(std::ceil(3.0 * std::sqrt(maxB / (2.0 * Pi * Pi)) * ppd));
  for (int k = 0; k < 3; ++k)
  {
    double sum[2] = { 0.0, 0.0 };
    Plane parts[2];
    const double as[2] = { a1[k], a2[k] }, bs[2] = { b1[k], b2[k] };
    for (int g = 0; g < 2; ++g)
    {
      if (as[g] == 0.0)
      {
        continue;
      }
      std::vector<double> g1 = Kernel(radius, [&](double px) {
        const double r = px / ppd;
        return std::exp(-Pi * Pi * r * r / bs[g]);
      });
      double s1 = 0.0;
      for (double v : g1)
      {
        s1 += v;
      }
      sum[g] = as[g] * std::sqrt(Pi / bs[g]) * s1 * s1; // the 2D kernel's sum
      NormalizeSum(g1);
      parts[g] = Convolve(ycc[k], w, h, g1, g1);
    }
    for (std::size_t i = 0; i < n; ++i)
    {
      double v = 0.0;
      for (int g = 0; g < 2; ++g)
      {
        v += sum[g] > 0.0 ? sum[g] * parts[g][i] : 0.0;
      }
      ycc[k][i] = v / (sum[0] + sum[1]);
    }
  }
  std::vector<Vec3> lab(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    Vec3 rgb = XyzToLinearRgb(YcxczToXyz({ ycc[0][i], ycc[1][i], ycc[2][i] }));
    for (double& c : rgb)
    {
      c = Clamp01(c);
    }
    lab[i] = HuntLab(rgb);
  }
  return lab;
}

// Edge and point feature magnitudes of the achromatic channel (normalized lightness).
void Features(const Image& im, double ppd, Plane& edges, Plane& points)
{
  const int w = im.Width, h = im.Height;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  Plane y(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const Vec3 c = XyzToYcxcz(LinearRgbToXyz(
      { Clamp01(im.Rgb[3 * i]), Clamp01(im.Rgb[3 * i + 1]), Clamp01(im.Rgb[3 * i + 2]) }));
    y[i] = (c[0] + 16.0) / 116.0;
  }
  const double sigma = 0.5 * 0.082 * ppd;
  const int radius = static_cast<int>(std::ceil(3.0 * sigma));
  auto gauss = [sigma](double x) { return std::exp(-x * x / (2.0 * sigma * sigma)); };
  std::vector<double> g = Kernel(radius, gauss);
  NormalizeSum(g);
  std::vector<double> d1 = Kernel(radius, [&](double x) { return -x * gauss(x); });
  NormalizeSigned(d1);
  std::vector<double> d2 =
    Kernel(radius, [&](double x) { return (x * x / (sigma * sigma) - 1.0) * gauss(x); });
  NormalizeSigned(d2);
  const Plane ex = Convolve(y, w, h, d1, g), ey = Convolve(y, w, h, g, d1);
  const Plane px = Convolve(y, w, h, d2, g), py = Convolve(y, w, h, g, d2);
  edges.resize(n);
  points.resize(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    edges[i] = std::hypot(ex[i], ey[i]);
    points[i] = std::hypot(px[i], py[i]);
  }
}
}

bool ReadPfm(const std::string& path, Image& image)
{
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  double scale = 0.0;
  in >> magic >> image.Width >> image.Height >> scale;
  in.get(); // the single whitespace before the data
  if (!in || magic != "PF" || scale >= 0.0 || image.Width <= 0 || image.Height <= 0)
  {
    return false;
  }
  image.Rgb.resize(static_cast<std::size_t>(image.Width) * image.Height * 3);
  in.read(reinterpret_cast<char*>(image.Rgb.data()),
    static_cast<std::streamsize>(image.Rgb.size() * sizeof(float)));
  return static_cast<bool>(in);
}

bool WritePfm(const std::string& path, const Image& image)
{
  std::ofstream out(path, std::ios::binary);
  out << "PF\n" << image.Width << " " << image.Height << "\n-1.0\n";
  out.write(reinterpret_cast<const char*>(image.Rgb.data()),
    static_cast<std::streamsize>(image.Rgb.size() * sizeof(float)));
  return static_cast<bool>(out);
}

Image FromRgba(const float* rgba, int width, int height)
{
  Image image;
  image.Width = width;
  image.Height = height;
  const std::size_t n = static_cast<std::size_t>(width) * height;
  image.Rgb.resize(3 * n);
  for (std::size_t i = 0; i < n; ++i)
  {
    std::copy(rgba + 4 * i, rgba + 4 * i + 3, image.Rgb.begin() + 3 * i);
  }
  return image;
}

double Rmse(const Image& test, const Image& reference)
{
  CheckSizes(test, reference);
  double sum = 0.0;
  for (std::size_t i = 0; i < test.Rgb.size(); ++i)
  {
    const double d = static_cast<double>(test.Rgb[i]) - reference.Rgb[i];
    sum += d * d;
  }
  return std::sqrt(sum / test.Rgb.size());
}

double RelMse(const Image& test, const Image& reference)
{
  CheckSizes(test, reference);
  double sum = 0.0;
  for (std::size_t i = 0; i < test.Rgb.size(); ++i)
  {
    const double r = reference.Rgb[i];
    const double d = test.Rgb[i] - r;
    sum += d * d / (r * r + 0.01);
  }
  return sum / test.Rgb.size();
}

double Ssim(const Image& test, const Image& reference)
{
  CheckSizes(test, reference);
  const int w = test.Width, h = test.Height;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  Plane x(n), y(n), xx(n), yy(n), xy(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    x[i] = Luminance(test, i);
    y[i] = Luminance(reference, i);
    xx[i] = x[i] * x[i];
    yy[i] = y[i] * y[i];
    xy[i] = x[i] * y[i];
  }
  std::vector<double> g = Kernel(5, [](double t) { return std::exp(-t * t / (2.0 * 1.5 * 1.5)); });
  NormalizeSum(g);
  const Plane mx = Convolve(x, w, h, g, g), my = Convolve(y, w, h, g, g);
  const Plane sxx = Convolve(xx, w, h, g, g), syy = Convolve(yy, w, h, g, g),
              sxy = Convolve(xy, w, h, g, g);
  const double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    const double vx = sxx[i] - mx[i] * mx[i], vy = syy[i] - my[i] * my[i];
    const double cov = sxy[i] - mx[i] * my[i];
    sum += (2.0 * mx[i] * my[i] + c1) * (2.0 * cov + c2) /
      ((mx[i] * mx[i] + my[i] * my[i] + c1) * (vx + vy + c2));
  }
  return sum / n;
}

double Flip(const Image& test, const Image& reference, double pixelsPerDegree)
{
  CheckSizes(test, reference);
  const double qc = 0.7, qf = 0.5, pc = 0.4, pt = 0.95;
  const std::vector<Vec3> labT = FilteredHuntLab(test, pixelsPerDegree);
  const std::vector<Vec3> labR = FilteredHuntLab(reference, pixelsPerDegree);
  Plane edgesT, pointsT, edgesR, pointsR;
  Features(test, pixelsPerDegree, edgesT, pointsT);
  Features(reference, pixelsPerDegree, edgesR, pointsR);
  // The largest colour difference: between green and blue.
  const double cmax = std::pow(HyAb(HuntLab({ 0.0, 1.0, 0.0 }), HuntLab({ 0.0, 0.0, 1.0 })), qc);
  double sum = 0.0;
  for (std::size_t i = 0; i < labT.size(); ++i)
  {
    const double e = std::pow(HyAb(labT[i], labR[i]), qc);
    const double colour = e < pc * cmax ? pt / (pc * cmax) * e
                                        : pt + (e - pc * cmax) / (cmax - pc * cmax) * (1.0 - pt);
    const double feature = std::pow(std::max(std::abs(edgesT[i] - edgesR[i]),
                                       std::abs(pointsT[i] - pointsR[i])) / std::sqrt(2.0),
      qf);
    sum += std::pow(colour, 1.0 - feature);
  }
  return sum / labT.size();
}
Errors Compare(const Image& test, const Image& reference)
{
  Errors e;
  e.Rmse = Rmse(test, reference);
  e.RelMse = RelMse(test, reference);
  e.Ssim = Ssim(test, reference);
  e.Flip = Flip(test, reference);
  return e;
}
}
}
