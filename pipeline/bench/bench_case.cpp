#include "pipeline/bench/bench_case.hpp"

#include "pipeline/api/eye_access.hpp"
#include "pipeline/bench/peak_memory.hpp"
#include "pipeline/memory/frame_buffer_pool.hpp"
#include "retina/display_encoding.hpp"

namespace eyestream::pipeline {

namespace {

Eye eye_for(const BenchScene& scene, const Settings& settings) {
  Eye eye = detail::EyeAccess::make(settings, scene.info);
  detail::EyeAccess::set_gaze(eye, std::make_shared<const GazeTimeline>(scene.gaze, scene.info.width / 2.0,
                                                                        scene.info.height / 2.0));
  return eye;
}

// One frame through a throwaway eye, untimed, so the timed frames find
// the buffer pool and the libraries warmed up, as
// every frame after the first of a long run does.
void warm_up(const BenchScene& scene, const Settings& settings) {
  Eye eye = eye_for(scene, settings);
  io::DisplayFrame out = detail::EyeAccess::process(eye, scene.frames.front(), scene.ends_s.front());
  cv::Mat code;
  retina::encode_display(out.linear, 8, scene.frames.front().index, detail::EyeAccess::plan(eye).encoding, code);
}

}  // namespace

BenchCase run_bench_case(const BenchScene& scene, const Settings& settings) {
  BenchCase c;
  // The outputs kept for the error against the reference, made and written
  // before anything is measured: a frame's output handed to the bench
  // never returns to the buffer pool, and a new image-sized buffer each
  // frame paid for its page faults inside the eye's timed stages.
  c.shown.resize(scene.frames.size());
  for (cv::Mat& shown : c.shown) shown = cv::Mat::zeros(scene.info.height, scene.info.width, CV_32FC3);
  release_frame_buffers();  // what earlier cases left in the pool is not this case's
  reset_peak_resident();
  const double resident_before = resident_mib();
  if (!scene.frames.empty()) warm_up(scene, settings);
  auto clock = std::chrono::steady_clock::now();
  Eye eye = eye_for(scene, settings);
  const Plan& plan = detail::EyeAccess::plan(eye);
  c.setup_s = lap_ms(clock) / 1000.0;
  cv::Mat code;
  for (size_t i = 0; i < scene.frames.size(); ++i) {
    lap_ms(clock);
    io::DisplayFrame out = detail::EyeAccess::process(eye, scene.frames[i], scene.ends_s[i]);
    const FrameReport& r = detail::EyeAccess::report(eye);
    c.wall_ms += lap_ms(clock);
    retina::encode_display(out.linear, 8, scene.frames[i].index, plan.encoding, code);
    const double encoding = lap_ms(clock);
    c.encode_ms += encoding;
    c.wall_ms += encoding;
    c.filter_ms += r.times.total();
    c.stage_ms += r.times;
    c.glare_frames += r.active.glare;
    c.retina_frames += r.active.retina;
    c.afterimage_frames += r.active.afterimages;
    c.mesopic_frames += r.active.mesopic;
    c.acuity_frames += r.active.acuity;
    if (!r.active.glare && !r.active.retina && !r.active.afterimages) {
      ++c.rest_frames;
      c.rest_ms += r.times.total();
    }
    out.linear.copyTo(c.shown[i]);
    ++c.frames;
  }
  c.memory_mib = peak_resident_mib() - resident_before;
  const double n = std::max(c.frames, 1);
  c.filter_ms /= n;
  c.rest_ms /= std::max(c.rest_frames, 1);
  c.encode_ms /= n;
  c.wall_ms /= n;
  c.stage_ms *= 1.0 / n;
  const RetinaStage& retina = detail::EyeAccess::simulator(eye).retina();
  c.bleached = retina.state().bleached().clone();
  c.deficit = retina.state().deficit().clone();
  c.calcium_max = retina.state().calcium_max();
  c.sites_per_pixel = plan.retina.sites_per_pixel;
  return c;
}

}  // namespace eyestream::pipeline
