#include "samples/scene_writer.hpp"

#include <filesystem>

#include "io/exr_file.hpp"
#include "io/frame_sequence.hpp"
#include "io/gaze_csv.hpp"
#include "io/png_file.hpp"

namespace eyestream::samples {

SceneWriter::SceneWriter(const std::string& out_dir, double fps, double white)
    : dir_(out_dir), fps_(fps), white_(white) {}

void SceneWriter::add_frame(const cv::Mat& rgb, const cv::Mat& target_mask) {
  const std::int64_t index = frames_++;
  io::StagedFile file(io::format_pattern(dir_ + "/frames/%05d.exr", index));
  cv::Mat scaled = rgb * (1.0 / white_);
  io::write_exr(file.temp_path().string(), scaled, io::ExrWriteOptions{true, white_, fps_});
  files_.push_back(std::move(file));
  masked_.push_back(!target_mask.empty());
  if (target_mask.empty()) return;
  const std::vector<unsigned char> png = io::encode_png(target_mask);
  io::StagedFile mask(io::format_pattern(dir_ + "/target/%05d.png", index));
  io::write_all(mask, png);
  files_.push_back(std::move(mask));
}

void SceneWriter::finish(const std::vector<io::GazeSample>& gaze) {
  io::write_gaze_csv(dir_ + "/gaze.csv", gaze);
  for (io::StagedFile& f : files_) f.commit();
  files_.clear();
  // A scene written over another: the old one's frames and masks beyond
  // this one's go, so the folder holds one scene.
  for (const bool masks : {false, true}) {
    const std::filesystem::path folder = std::filesystem::path(dir_) / (masks ? "target" : "frames");
    if (!std::filesystem::is_directory(folder)) continue;
    for (const auto& e : std::filesystem::directory_iterator(folder)) {
      const std::string stem = e.path().stem().string();
      const bool numbered =
          stem.size() >= 5 && stem.size() <= 12 && stem.find_first_not_of("0123456789") == std::string::npos;
      if (!numbered) continue;
      const std::int64_t n = std::stoll(stem);
      const bool written = n < frames_ && (!masks || masked_[size_t(n)]);
      if (!written) std::filesystem::remove(e.path());
    }
  }
}

}  // namespace eyestream::samples
