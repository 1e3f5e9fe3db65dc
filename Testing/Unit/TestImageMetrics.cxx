// Metrics on images with known answers: identical images, uniform offsets and contrasts whose
// values follow from the definitions and standard CIELAB values.
#include "ImageMetrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <random>

using voxelgi::metrics::Image;

namespace
{
Image Uniform(int w, int h, double r, double g, double b)
{
  Image im;
  im.Width = w;
  im.Height = h;
  for (int i = 0; i < w * h; ++i)
  {
    im.Rgb.insert(im.Rgb.end(), { float(r), float(g), float(b) });
  }
  return im;
}

Image Noisy(const Image& base, double amplitude, unsigned seed)
{
  Image im = base;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (float& v : im.Rgb)
  {
    v += float(amplitude) * u(rng);
  }
  return im;
}
}

TEST(ImageMetrics, IdenticalImagesHaveNoError)
{
  const Image im = Noisy(Uniform(48, 40, 0.4, 0.5, 0.6), 0.3, 1);
  EXPECT_DOUBLE_EQ(voxelgi::metrics::Rmse(im, im), 0.0);
  EXPECT_DOUBLE_EQ(voxelgi::metrics::RelMse(im, im), 0.0);
  EXPECT_NEAR(voxelgi::metrics::Ssim(im, im), 1.0, 1e-9);
  EXPECT_NEAR(voxelgi::metrics::Flip(im, im), 0.0, 1e-9);
}

TEST(ImageMetrics, UniformOffset)
{
  const Image ref = Uniform(16, 16, 0.3, 0.3, 0.3);
  const Image test = Uniform(16, 16, 0.4, 0.4, 0.4);
  EXPECT_NEAR(voxelgi::metrics::Rmse(test, ref), 0.1, 1e-6);
  // 0.1^2 / (0.3^2 + 0.01)
  EXPECT_NEAR(voxelgi::metrics::RelMse(test, ref), 0.1, 1e-5);
}

TEST(ImageMetrics, SsimOfUniformImagesIsTheLuminanceTerm)
{
  // No variance: SSIM = (2 mx my + C1) / (mx^2 + my^2 + C1).
  const Image a = Uniform(20, 20, 0.2, 0.2, 0.2);
  const Image b = Uniform(20, 20, 0.6, 0.6, 0.6);
  EXPECT_NEAR(voxelgi::metrics::Ssim(a, b), (0.24 + 1e-4) / (0.40 + 1e-4), 1e-6);
}

TEST(ImageMetrics, FlipOfBlackAgainstWhite)
{
  // Uniform images: no features, and the contrast filters keep a constant. HyAB(black, white)
  // = 100; the maximal difference is HyAB between Hunt-adjusted sRGB green
  // (L 87.735, a -86.183, b 83.179) and blue (L 32.303, a 79.197, b -107.864) = 203.30.
  // With qc = 0.7, pc = 0.4, pt = 0.95: 100^0.7 = 25.119, cmax = 41.282, so the error is
  // 0.95 + (25.119 - 0.4 * 41.282) / (0.6 * 41.282) * 0.05 = 0.9674.
  const Image black = Uniform(24, 24, 0.0, 0.0, 0.0);
  const Image white = Uniform(24, 24, 1.0, 1.0, 1.0);
  EXPECT_NEAR(voxelgi::metrics::Flip(black, white), 0.9674, 1e-3);
  EXPECT_NEAR(voxelgi::metrics::Flip(white, black), 0.9674, 1e-3);
}

TEST(ImageMetrics, FlipOfSmallColourDifference)
{
  // Grey 0.5 against grey 0.5 + d, d small: below pc * cmax the error is linear,
  // pt / (pc cmax) * (delta L)^0.7, with delta L from CIELAB's lightness of the two greys.
  const Image a = Uniform(24, 24, 0.5, 0.5, 0.5);
  const Image b = Uniform(24, 24, 0.55, 0.55, 0.55);
  auto lightness = [](double y) { return 116.0 * std::cbrt(y) - 16.0; };
  const double dl = lightness(0.55) - lightness(0.5);
  const double expected = 0.95 / (0.4 * 41.2816) * std::pow(dl, 0.7);
  EXPECT_NEAR(voxelgi::metrics::Flip(a, b), expected, 2e-3);
}

TEST(ImageMetrics, MoreNoiseIsWorse)
{
  const Image ref = Uniform(64, 64, 0.5, 0.4, 0.3);
  const Image little = Noisy(ref, 0.02, 2), much = Noisy(ref, 0.2, 3);
  EXPECT_LT(voxelgi::metrics::Rmse(little, ref), voxelgi::metrics::Rmse(much, ref));
  EXPECT_LT(voxelgi::metrics::RelMse(little, ref), voxelgi::metrics::RelMse(much, ref));
  EXPECT_GT(voxelgi::metrics::Ssim(little, ref), voxelgi::metrics::Ssim(much, ref));
  const double flipLittle = voxelgi::metrics::Flip(little, ref);
  const double flipMuch = voxelgi::metrics::Flip(much, ref);
  EXPECT_GT(flipLittle, 0.0);
  EXPECT_LT(flipLittle, flipMuch);
  EXPECT_LE(flipMuch, 1.0);
}

TEST(ImageMetrics, MismatchedSizesThrow)
{
  EXPECT_THROW(voxelgi::metrics::Rmse(Uniform(4, 4, 0, 0, 0), Uniform(4, 5, 0, 0, 0)),
    std::invalid_argument);
}

TEST(ImageMetrics, FloatMapRoundTripAndRgba)
{
  const float rgba[8] = { 0.1f, 0.2f, 0.3f, 1.0f, 4.0f, 5.0f, 6.0f, 0.0f };
  const Image image = voxelgi::metrics::FromRgba(rgba, 2, 1);
  ASSERT_EQ(image.Rgb.size(), 6u);
  EXPECT_FLOAT_EQ(image.Rgb[3], 4.0f); // alpha dropped
  const std::string path = ::testing::TempDir() + "voxelgi-metrics.pfm";
  {
    std::ofstream out(path, std::ios::binary);
    out << "PF\n2 1\n-1.0\n";
    out.write(reinterpret_cast<const char*>(image.Rgb.data()), 6 * sizeof(float));
  }
  Image read;
  ASSERT_TRUE(voxelgi::metrics::ReadPfm(path, read));
  EXPECT_EQ(read.Width, 2);
  EXPECT_EQ(read.Height, 1);
  EXPECT_EQ(read.Rgb, image.Rgb);
  EXPECT_FALSE(voxelgi::metrics::ReadPfm(path + ".missing", read));

  // WritePfm writes the same bytes as the map written by hand above.
  const std::string written = ::testing::TempDir() + "voxelgi-metrics-written.pfm";
  ASSERT_TRUE(voxelgi::metrics::WritePfm(written, image));
  std::ifstream a(path, std::ios::binary), b(written, std::ios::binary);
  const std::string byHand((std::istreambuf_iterator<char>(a)), std::istreambuf_iterator<char>());
  const std::string byWritePfm(
    (std::istreambuf_iterator<char>(b)), std::istreambuf_iterator<char>());
  EXPECT_EQ(byWritePfm, byHand);
}
