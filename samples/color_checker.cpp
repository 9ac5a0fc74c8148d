#include "samples/color_checker.hpp"

#include <cmath>

namespace eyestream::samples {

namespace {

float srgb_to_linear(int code) {
  const double v = code / 255.0;
  return float(v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4));
}

}  // namespace

const std::array<cv::Vec3f, 24>& color_checker_linear() {
  static const std::array<cv::Vec3f, 24> patches = [] {
    const int srgb[24][3] = {{115, 82, 68},   {194, 150, 130}, {98, 122, 157}, {87, 108, 67},   {133, 128, 177},
                             {103, 189, 170}, {214, 126, 44},  {80, 91, 166},  {193, 90, 99},   {94, 60, 108},
                             {157, 188, 64},  {224, 163, 46},  {56, 61, 150},  {70, 148, 73},   {175, 54, 60},
                             {231, 199, 31},  {187, 86, 149},  {8, 133, 161},  {243, 243, 242}, {200, 200, 200},
                             {160, 160, 160}, {122, 122, 121}, {85, 85, 85},   {52, 52, 52}};
    std::array<cv::Vec3f, 24> out;
    for (int i = 0; i < 24; ++i)
      out[size_t(i)] = cv::Vec3f(srgb_to_linear(srgb[i][0]), srgb_to_linear(srgb[i][1]), srgb_to_linear(srgb[i][2]));
    return out;
  }();
  return patches;
}

}  // namespace eyestream::samples
