#include "pipeline/preview/hdr10_encoding.hpp"

#include <cmath>

#include "io/primaries.hpp"
#include "io/transfer_functions.hpp"

namespace eyestream::pipeline {

void encode_hdr10(const cv::Mat& linear, double display_peak_cd_m2, cv::Mat& code) {
  const cv::Matx33d to_2020 = io::to_rec709_matrix(io::bt2020_chromaticities()).inv();
  code.create(linear.size(), CV_16UC3);
  cv::parallel_for_(cv::Range(0, linear.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      const cv::Vec3f* in = linear.ptr<cv::Vec3f>(y);
      cv::Vec3w* out = code.ptr<cv::Vec3w>(y);
      for (int x = 0; x < linear.cols; ++x) {
        const cv::Vec3d rgb2020 = to_2020 * cv::Vec3d(in[x][0], in[x][1], in[x][2]);
        for (int c = 0; c < 3; ++c) {
          const double l = std::isfinite(rgb2020[c]) ? std::max(rgb2020[c], 0.0) * display_peak_cd_m2 : 0.0;
          out[x][c] = cv::saturate_cast<unsigned short>(std::lround(io::luminance_to_pq(l) * 65535.0));
        }
      }
    }
  });
}

}  // namespace eyestream::pipeline
