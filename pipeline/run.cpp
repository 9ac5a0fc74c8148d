#include "pipeline/run.hpp"

#include <cstdio>
#include <memory>
#include <opencv2/core.hpp>
#include <sstream>

#include "io/error.hpp"
#include "io/exr_sequence_source.hpp"
#include "io/gaze_import.hpp"
#include "io/library_logging.hpp"
#include "io/sink_factory.hpp"
#include "pipeline/eye_simulator.hpp"
#include "pipeline/gaze_timeline.hpp"
#include "pipeline/plan.hpp"
#include "pipeline/progress.hpp"
#include "pipeline/report_writer.hpp"

namespace eyestream::pipeline {

std::string RunSummary::one_line() const {
  std::ostringstream o;
  o.precision(3);
  o << "eyestream: " << frames << " frames in " << wall_s << " s (" << (wall_s > 0 ? frames / wall_s : 0.0)
    << " fps) -> " << output << "; final adaptation " << final_adaptation_log << " log10 cd/m^2";
  if (nonfinite_pixels) o << "; " << nonfinite_pixels << " non-finite pixels shown black";
  return o.str();
}

namespace {

io::GazeImportOptions gaze_import_options(const Settings& s, const io::SourceInfo& info) {
  io::GazeImportOptions o;
  const std::string& f = s.gaze_format;
  o.format = f == "native"       ? io::GazeFormat::kNative
             : f == "pupil-core" ? io::GazeFormat::kPupilCore
             : f == "neon"       ? io::GazeFormat::kNeon
             : f == "tobii"      ? io::GazeFormat::kTobii
             : f == "eyelink"    ? io::GazeFormat::kEyeLink
                                 : io::GazeFormat::kAuto;
  o.units = s.gaze_units == "norm" ? io::GazeUnits::kNormalised : io::GazeUnits::kPixels;
  o.frame_width = info.width;
  o.frame_height = info.height;
  o.source_width = s.gaze_source_width;
  o.source_height = s.gaze_source_height;
  o.min_confidence = s.gaze_confidence;
  o.offset_s = s.gaze_offset_s;
  o.sync_clock = s.gaze_sync_s;
  return o;
}

}  // namespace

std::string describe_run(const Settings& s) {
  io::ExrSequenceSource source(s.input, s.exr);
  const Plan plan = compile_plan(s, source.info(), io::sink_needs(s.output, s.sink));
  return s.input + ": " + source.info().description + "\n" + plan.describe();
}

RunSummary run(const Settings& s) {
  cv::setNumThreads(s.threads > 0 ? s.threads : -1);
  io::set_library_verbosity(s.verbose);
  io::ExrSequenceSource source(s.input, s.exr);
  const io::SourceInfo& info = source.info();
  std::vector<io::GazeSample> samples;
  if (!s.gaze.empty()) samples = io::read_gaze(s.gaze, gaze_import_options(s, info));
  io::SinkOptions sink_options = s.sink;
  sink_options.video.frames_per_second = info.frames_per_second;
  std::unique_ptr<io::FrameSink> sink = io::make_sink(s.output, sink_options);
  const Plan plan = compile_plan(s, info, sink->needs());
  if (s.verbose) std::fprintf(stderr, "%s: %s\n%s", s.input.c_str(), info.description.c_str(), plan.describe().c_str());
  EyeSimulator eye(plan);
  const GazeTimeline timeline(samples, info.width / 2.0, info.height / 2.0);

  RunSummary summary;
  summary.output = s.output;
  Progress progress(info.frame_count, s.progress);
  std::optional<ReportWriter> report_writer;
  if (!s.report.empty()) report_writer.emplace(s.report, s.viewer.age_years);
  std::optional<io::SceneFrame> current = source.next();
  while (current) {
    std::optional<io::SceneFrame> next = source.next();
    const double t1 = next ? next->time_s : current->time_s + 1.0 / info.frames_per_second;
    FrameReport report;
    const io::DisplayFrame shown = eye.process(*current, timeline.segments(current->time_s, t1), &report);
    if (report.nonfinite_pixels > 0 && s.bad_pixels == "fail")
      throw InputError(current->source + ": frame " + std::to_string(current->index) + " has " +
                       std::to_string(report.nonfinite_pixels) +
                       " NaN or infinite pixels (--bad-pixels clamp to go on)");
    sink->write(shown);
    if (report_writer) report_writer->add(current->index, current->time_s, report);
    if (!s.state_exr.empty() && current->index == s.state_frame) eye.retina().write_state(s.state_exr);
    summary.nonfinite_pixels += report.nonfinite_pixels;
    if (s.verbose)
      std::fprintf(stderr, "frame %lld t=%.3f s gaze=(%.1f,%.1f)%s adaptation=%.3f target=%.3f glare=%s\n",
                   (long long)current->index, current->time_s, report.gaze_x, report.gaze_y,
                   report.eye_closed ? " closed" : "", report.adaptation_log, report.target_log,
                   report.glare_ran ? "ran" : "skipped (nothing above the display peak)");
    ++summary.frames;
    progress.frame_done();
    current = std::move(next);
  }
  sink->finish();
  if (report_writer) report_writer->finish();
  progress.finish();
  summary.wall_s = progress.elapsed_s();
  summary.final_adaptation_log = eye.adaptation_log();
  return summary;
}

}  // namespace eyestream::pipeline
