#include "samples/scene_writer.hpp"

#include <filesystem>

#include "io/exr_file.hpp"
#include "io/frame_sequence.hpp"
#include "io/gaze_csv.hpp"

namespace eyestream::samples {

SceneWriter::SceneWriter(const std::string& out_dir, double fps, double white)
    : dir_(out_dir), fps_(fps), white_(white) {}

void SceneWriter::add_frame(const cv::Mat& rgb) {
  const std::string path = io::format_pattern(dir_ + "/frames/%05d.exr", std::int64_t(files_.size()));
  io::StagedFile file(path);
  cv::Mat scaled = rgb * (1.0 / white_);
  io::write_exr(file.temp_path().string(), scaled, io::ExrWriteOptions{true, white_, fps_});
  files_.push_back(std::move(file));
}

void SceneWriter::finish(const std::vector<io::GazeSample>& gaze) {
  io::write_gaze_csv(dir_ + "/gaze.csv", gaze);
  for (io::StagedFile& f : files_) f.commit();
  files_.clear();
}

}  // namespace eyestream::samples
