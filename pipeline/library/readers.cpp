#include "eyestream/readers.hpp"

#include "pipeline/api/api_settings.hpp"
#include "io/frame_source.hpp"
#include "io/gaze_import.hpp"
#include "pipeline/run/run_inputs.hpp"

namespace eyestream {

struct FrameReader::Impl {
  std::unique_ptr<io::FrameSource> source;
};

FrameReader::FrameReader(const std::string& path, const std::map<std::string, std::string>& settings)
    : impl_(std::make_unique<Impl>()) {
  translated([&] {
    pipeline::Settings s = compile_settings(settings);
    s.input = path;
    impl_->source = pipeline::open_input(s);
    return 0;
  });
}

FrameReader::~FrameReader() = default;
FrameReader::FrameReader(FrameReader&&) noexcept = default;
FrameReader& FrameReader::operator=(FrameReader&&) noexcept = default;

int FrameReader::width() const { return impl_->source->info().width; }
int FrameReader::height() const { return impl_->source->info().height; }
double FrameReader::fps() const { return impl_->source->info().frames_per_second; }
std::int64_t FrameReader::frame_count() const { return impl_->source->info().frame_count; }
std::string FrameReader::description() const { return impl_->source->info().description; }

bool FrameReader::next(InputFrame& frame) {
  return translated([&] {
    std::optional<io::SceneFrame> f = impl_->source->next();
    if (!f) return false;
    frame.rgb_cd_m2 = f->rgb;
    frame.time_s = f->time_s;
    frame.index = f->index;
    return true;
  });
}

std::vector<Gaze> read_gaze(const std::string& path, int width, int height, double fps,
                            const std::map<std::string, std::string>& settings) {
  return translated([&] {
    if (width < 1 || height < 1 || !(fps > 0.0))
      throw UsageError("read_gaze: needs a positive frame size and rate");
    const pipeline::Settings s = compile_settings(settings);
    io::SourceInfo info;
    info.width = width;
    info.height = height;
    info.frames_per_second = fps;
    std::vector<Gaze> out;
    for (const io::GazeSample& g : io::read_gaze(path, pipeline::gaze_import_options(s, info))) {
      Gaze o;
      o.t_s = g.t_s;
      o.x = g.x;
      o.y = g.y;
      o.closed = g.state == io::EyeState::kClosed;
      o.lost = g.state == io::EyeState::kLost;
      if (io::has_usable_pupil(g)) o.pupil_mm = g.pupil_mm;
      out.push_back(o);
    }
    return out;
  });
}

}  // namespace eyestream
