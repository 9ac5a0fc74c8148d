#include "io/image_sequence_sink.hpp"

#include "io/png_file.hpp"

#include <opencv2/imgproc.hpp>

#include "io/error.hpp"
#include "io/exr_file.hpp"
#include "io/frame_sequence.hpp"

namespace eyestream::io {

ImageSequenceSink::ImageSequenceSink(std::string pattern, ImageFormat format, std::int64_t first_number,
                                     double frames_per_second, double png_gamma, ExrCompression exr_compression)
    : pattern_(std::move(pattern)),
      format_(format),
      first_number_(first_number),
      frames_per_second_(frames_per_second),
      png_gamma_(png_gamma),
      exr_compression_(exr_compression) {}

SinkNeeds ImageSequenceSink::needs() const {
  switch (format_) {
    case ImageFormat::kPng8: return SinkNeeds::kCode8;
    case ImageFormat::kPng16: return SinkNeeds::kCode16;
    case ImageFormat::kExr: break;
  }
  return SinkNeeds::kLinear;
}

namespace {

constexpr const char* kTag = "frame";

}  // namespace

ImageSequenceSink::~ImageSequenceSink() {
  std::error_code ec;
  for (const auto& [first, last] : staged_)
    for (std::int64_t n = first; n <= last; ++n) std::filesystem::remove(staged_temp_path(format_pattern(pattern_, n), kTag), ec);
}

void ImageSequenceSink::write(const DisplayFrame& frame) {
  if (written_ + staged_count_ > 0 && !is_printf_pattern(pattern_))
    throw OutputError(pattern_ + ": more than one frame needs a numbered pattern such as out/%05d.png");
  const std::int64_t number = first_number_ + frame.index;
  StagedFile file(format_pattern(pattern_, number), kTag);
  if (format_ == ImageFormat::kExr) {
    write_exr(file.temp_path().string(), frame.linear,
              ExrWriteOptions{false, std::nullopt,
                              frames_per_second_ > 0 ? std::optional<double>(frames_per_second_) : std::nullopt,
                              exr_compression_});
  } else {
    cv::Mat bgr;
    cv::cvtColor(frame.code, bgr, cv::COLOR_RGB2BGR);
    const std::vector<unsigned char> bytes = encode_png(bgr, png_gamma_);
    if (bytes.empty()) throw OutputError(file.final_path().string() + ": PNG encoding failed");
    write_all(file, bytes);
  }
  file.release();
  if (!staged_.empty() && staged_.back().second + 1 == number)
    staged_.back().second = number;
  else
    staged_.push_back({number, number});
  ++staged_count_;
}

void ImageSequenceSink::finish() {
  if (written_ == 0 && staged_count_ == 0) throw OutputError(pattern_ + ": no frame was written");
  commit_so_far();
}

bool ImageSequenceSink::commit_so_far() {
  while (!staged_.empty()) {
    auto& [first, last] = staged_.front();
    for (; first <= last; ++first) {
      const std::filesystem::path final_path = format_pattern(pattern_, first);
      std::error_code ec;
      std::filesystem::rename(staged_temp_path(final_path, kTag), final_path, ec);
      if (ec) throw OutputError(final_path.string() + ": cannot move finished output into place: " + ec.message());
      ++written_;
      --staged_count_;
    }
    staged_.erase(staged_.begin());
  }
  return true;
}

}  // namespace eyestream::io
