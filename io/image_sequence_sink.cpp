#include "io/image_sequence_sink.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "io/error.hpp"
#include "io/exr_file.hpp"
#include "io/frame_sequence.hpp"

namespace eyestream::io {

ImageSequenceSink::ImageSequenceSink(std::string pattern, ImageFormat format, std::int64_t first_number)
    : pattern_(std::move(pattern)), format_(format), first_number_(first_number) {}

SinkNeeds ImageSequenceSink::needs() const {
  switch (format_) {
    case ImageFormat::kPng8: return SinkNeeds::kCode8;
    case ImageFormat::kPng16: return SinkNeeds::kCode16;
    case ImageFormat::kExr: break;
  }
  return SinkNeeds::kLinear;
}

void ImageSequenceSink::write(const DisplayFrame& frame) {
  if (written_ + std::int64_t(files_.size()) > 0 && !is_printf_pattern(pattern_))
    throw OutputError(pattern_ + ": more than one frame needs a numbered pattern such as out/%05d.png");
  StagedFile file(format_pattern(pattern_, first_number_ + frame.index));
  if (format_ == ImageFormat::kExr) {
    write_exr(file.temp_path().string(), frame.linear, ExrWriteOptions{false, std::nullopt, std::nullopt});
  } else {
    cv::Mat bgr;
    cv::cvtColor(frame.code, bgr, cv::COLOR_RGB2BGR);
    std::vector<unsigned char> bytes;
    if (!cv::imencode(".png", bgr, bytes)) throw OutputError(file.final_path().string() + ": PNG encoding failed");
    write_all(file, bytes);
  }
  files_.push_back(std::move(file));
}

void ImageSequenceSink::finish() {
  if (written_ == 0 && files_.empty()) throw OutputError(pattern_ + ": no frame was written");
  commit_so_far();
}

bool ImageSequenceSink::commit_so_far() {
  for (StagedFile& f : files_) f.commit();
  written_ += std::int64_t(files_.size());
  files_.clear();
  return true;
}

}  // namespace eyestream::io
