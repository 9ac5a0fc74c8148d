// PNG (8 or 16 bit, display-encoded) and EXR (float, display-linear)
// sequences, one file per frame, named by a printf pattern.
#pragma once

#include <string>
#include <vector>

#include "io/exr_file.hpp"
#include "io/frame_sink.hpp"
#include "io/staged_file.hpp"

namespace eyestream::io {

enum class ImageFormat { kPng8, kPng16, kExr };

// Frame k is written to format_pattern(pattern, k + first_number). All files
// are staged and appear together at finish(); a sink destroyed before
// finish() removes them. A pattern with no %d is accepted for a one-frame
// run; a second frame then is an OutputError.
class ImageSequenceSink : public FrameSink {
 public:
  // EXR frames carry frames_per_second (when > 0) as framesPerSecond.
  // PNG frames carry `png_gamma` (code = light^gamma) as their gAMA.
  ImageSequenceSink(std::string pattern, ImageFormat format, std::int64_t first_number = 0,
                    double frames_per_second = 0.0, double png_gamma = 1.0 / 2.2,
                    ExrCompression exr_compression = ExrCompression::kZip);
  SinkNeeds needs() const override;
  void write(const DisplayFrame& frame) override;
  void finish() override;
  bool commit_so_far() override;
  ~ImageSequenceSink() override;

 private:
  // The staged frames, as runs of consecutive frame numbers: memory stays
  // flat however long the sequence (each temporary is found again from its
  // final name, io::staged_temp_path).
  std::string pattern_;
  ImageFormat format_;
  std::int64_t first_number_;
  double frames_per_second_;
  double png_gamma_;
  ExrCompression exr_compression_;
  std::vector<std::pair<std::int64_t, std::int64_t>> staged_;  // [first, last] numbers
  std::int64_t staged_count_ = 0;
  std::int64_t written_ = 0;
};

}  // namespace eyestream::io
