// A reduced 3-channel image's rows enlarged across (as cv::resize
// INTER_LINEAR's horizontal pass, through a BilinearAxis), the last two
// kept: a stripe of full-size rows reads each reduced row for about
// 1 / scale rows in turn and widens it once. The caller blends the two
// rows down.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "retina/bilinear_rows.hpp"

namespace eyestream::retina {

// A reduced map's rows enlarged across, the last two kept: a stripe of
// output rows reads each of them for about 1 / scale rows in turn.
class EnlargedRows {
 public:
  EnlargedRows(const cv::Mat& map, const BilinearAxis& across, int n) : map_(map), across_(across), n_(n) {
    for (auto& r : rows_) r.resize(size_t(n) * 3);
  }
  // Row i enlarged; valid until a row other than i and the one asked for
  // just before it is asked for.
  const float* row(int i) {
    int k = index_[0] == i ? 0 : index_[1] == i ? 1 : -1;
    if (k < 0) {  // replaces the row not asked for last
      k = 1 - last_;
      index_[k] = i;
      enlarge_row3(map_.ptr<float>(i), across_, rows_[k].data(), n_);
    }
    last_ = k;
    return rows_[k].data();
  }

 private:
  const cv::Mat& map_;
  const BilinearAxis& across_;
  int n_;
  std::vector<float> rows_[2];
  int index_[2] = {-1, -1};
  int last_ = 1;
};

}  // namespace eyestream::retina
