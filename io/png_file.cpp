#include "io/png_file.hpp"

#include <opencv2/imgcodecs.hpp>
#include <vector>

#include "io/error.hpp"
#include "io/staged_file.hpp"

namespace eyestream::io {

StagedFile stage_png(const std::filesystem::path& path, const cv::Mat& bgr) {
  std::vector<unsigned char> png;
  if (!cv::imencode(".png", bgr, png)) throw OutputError(path.string() + ": PNG encoding failed");
  StagedFile file(path);
  write_all(file, png);
  return file;
}

void write_png(const std::filesystem::path& path, const cv::Mat& bgr) { stage_png(path, bgr).commit(); }

}  // namespace eyestream::io
