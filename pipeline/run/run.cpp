#include "pipeline/run/run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <opencv2/core.hpp>
#include <sstream>

#include "io/background_sink.hpp"
#include "io/error.hpp"
#include "io/frame_sequence.hpp"
#include "io/gaze_import.hpp"
#include "io/gaze_summary.hpp"
#include "io/library_logging.hpp"
#include "io/prefetch_source.hpp"
#include "io/sink_factory.hpp"
#include "io/source_factory.hpp"
#include "io/staged_file.hpp"
#include "pipeline/memory/frame_buffer_pool.hpp"
#include "pipeline/run/output_paths.hpp"
#include "pipeline/run/checkpoint.hpp"
#include "pipeline/run/interrupts.hpp"
#include "pipeline/preview/preview_renderer.hpp"
#include "pipeline/run/progress.hpp"
#include "pipeline/report/report_writer.hpp"
#include "pipeline/run/run_inputs.hpp"
#include "pipeline/eye/target_region.hpp"

namespace eyestream::pipeline {

Interrupted::Interrupted(int sig)
    : std::runtime_error(std::string("interrupted by ") + signal_name(sig) + " before any frame was written; nothing kept"),
      signal(sig) {}

std::string RunSummary::one_line() const {
  std::ostringstream o;
  o.precision(3);
  if (!gaze.empty()) o << "eyestream: " << gaze << "\n";
  if (interrupted_by) o << "eyestream: interrupted by " << signal_name(interrupted_by) << "; kept the first ";
  else o << "eyestream: ";
  o << frames << " frames in " << wall_s << " s (" << (wall_s > 0 ? frames / wall_s : 0.0)
    << " fps) -> " << output << "; final adaptation " << final_adaptation_log << " log10 cd/m^2";
  if (!checkpoint.empty()) o << "; checkpoint " << checkpoint << " resumes at the next frame (--resume)";
  if (nonfinite_pixels) o << "; " << nonfinite_pixels << " non-finite pixels shown black";
  return o.str();
}

namespace {

// Decoding and encoding on threads of their own beside the eye, unless the
// run is held to one thread. The frames and their order do not change.
bool overlap_io(const Settings& s) { return s.threads != 1; }

struct LoadedGaze {
  std::vector<io::GazeSample> samples;
  std::optional<io::GazeSummary> summary;  // when there is a log
};

// The gaze log and what it holds against the video (gaze_summary.hpp).
LoadedGaze load_gaze(const Settings& s, const io::SourceInfo& info) {
  LoadedGaze g;
  if (s.gaze.empty() && s.pupil_from_gaze)
    throw UsageError("--pupil-from-gaze needs a gaze log with pupil diameters (-g)");
  if (s.gaze_pupils != "auto" && s.gaze_pupils != "none" && !s.pupil_from_gaze)
    throw UsageError("--gaze-pupils " + s.gaze_pupils + " reads pupils for --pupil-from-gaze, which is not set");
  if (s.gaze.empty()) return g;
  const io::GazeImportOptions o = gaze_import_options(s, info);
  io::GazeRead read;
  g.samples = io::read_gaze(s.gaze, o, &read);
  const double end_s =
      info.frame_count > 0 && info.frames_per_second > 0 ? double(info.frame_count) / info.frames_per_second : -1.0;
  g.summary = io::summarise_gaze(g.samples, read.format, info.width, info.height, end_s);
  g.summary->notes = read.notes;
  if (s.pupil_from_gaze && std::none_of(g.samples.begin(), g.samples.end(), io::has_usable_pupil)) {
    std::string why = read.format == io::GazeFormat::kEyeLink
                          ? " (EyeLink: give millimetres per pupil unit with --gaze-pupil-scale)"
                      : read.format == io::GazeFormat::kTobii  ? " (Tobii: Pupil diameter left/right)"
                      : read.format == io::GazeFormat::kNative ? " (native logs: a pupil_mm column)"
                                                               : " (Pupil Core: pupil_positions.csv, Neon: 3d_eye_states.csv, "
                                                                 "beside the export or named with --gaze-pupils)";
    for (const std::string& n : read.notes) why += "; " + n;  // e.g. the diameters left out
    throw InputError(s.gaze + ": --pupil-from-gaze: the log records no pupil diameter" + why);
  }
  return g;
}

// The refusals `run` makes before any work (and --print-plan with it):
// the frame range, the outputs, outputs that exist, the checkpoint options.
void refuse_before_work(const Settings& s, const io::SourceInfo& info) {
  if (s.end_frame != 0 && s.end_frame <= s.start_frame)
    throw UsageError("--end-frame " + std::to_string(s.end_frame) + " must be after --start-frame " +
                     std::to_string(s.start_frame));
  check_outputs(run_outputs(s));
  if (!s.overwrite && !s.resume) {
    const std::int64_t end = info.frame_count > 0 && (s.end_frame == 0 || s.end_frame > info.frame_count)
                                 ? info.frame_count
                                 : s.end_frame != 0 && info.frame_count > 0 ? s.end_frame : -1;
    refuse_existing(run_outputs(s), s.start_frame, end);
  }
  if ((s.checkpoint_every > 0 || s.resume) && s.checkpoint.empty())
    throw UsageError("--checkpoint-every and --resume need --checkpoint FILE");
  const std::string ext = io::lower_extension(s.output);
  if (s.checkpoint_every > 0 && (s.output == "-" || (ext != ".png" && ext != ".exr")))
    throw UsageError("--checkpoint-every needs a PNG or EXR frame output; split a video with `eyestream chunks`");
}

}  // namespace

std::string describe_run(const Settings& s) {
  const std::unique_ptr<io::FrameSource> source = open_input(s);
  refuse_before_work(s, source->info());  // what `run` would refuse, refused here too
  const PreviewRenderer renderer(s, source->info(), io::sink_needs(s.output, s.sink));
  std::string text = s.input + ": " + source->info().description + "\n" + renderer.describe();
  const LoadedGaze gaze = load_gaze(s, source->info());  // refused here as `run` would refuse it
  if (gaze.summary) {
    text += gaze.summary->line() + "\n";
    for (const std::string& n : gaze.summary->notes) text += "gaze: " + n + "\n";
    for (const std::string& w : gaze.summary->warnings) text += "warning: " + w + "\n";
  }
  return text;
}

namespace {

std::unique_ptr<ReportWriter> report_writer(const Settings& s, const PreviewRenderer& renderer) {
  if (s.report.empty()) return nullptr;
  std::vector<ReportViewer> viewers;
  for (size_t i = 0; i < renderer.panels(); ++i)
    if (renderer.spec(i).viewer)
      viewers.push_back({renderer.spec(i).label, renderer.spec(i).settings.viewer.age_years});
  return std::make_unique<ReportWriter>(s.report, std::move(viewers));
}

void log_frame(const io::SceneFrame& frame, const FrameReport& r) {
  const auto ran = [](bool on) { return on ? "ran" : "skipped"; };
  std::fprintf(stderr,
               "frame %lld t=%.3f s gaze=(%.1f,%.1f)%s adaptation=%.3f target=%.3f glare=%s%s retina=%s%s "
               "afterimages=%s mesopic=%s acuity=%s (%.1f ms)\n",
               (long long)frame.index, frame.time_s, r.gaze_x, r.gaze_y, r.eye_closed ? " closed" : "",
               r.adaptation_log, r.target_log, ran(r.active.glare),
               r.active.glare ? "" : " (nothing above the display peak)", ran(r.active.retina),
               r.active.retina ? "" : " (at rest)", ran(r.active.afterimages), ran(r.active.mesopic),
               ran(r.active.acuity), r.times.total());
}

// Checks the checkpoint options and, with --resume, restores the eyes and
// the report from the checkpoint; returns the first frame still to write.
std::int64_t prepare_checkpoints(const Settings& s, const std::string& settings, io::FrameSink& sink,
                                 PreviewRenderer& renderer, ReportWriter* report) {
  if ((s.checkpoint_every > 0 || s.resume) && s.checkpoint.empty())
    throw UsageError("--checkpoint-every and --resume need --checkpoint FILE");
  if (s.checkpoint_every > 0 && !sink.commit_so_far())
    throw UsageError("--checkpoint-every needs a PNG or EXR frame output; split a video with `eyestream chunks`");
  if (!s.resume) return 0;
  const Checkpoint c = read_checkpoint(s.checkpoint);
  const std::string mismatch = checkpoint_mismatch(s.checkpoint, c, settings);
  if (!mismatch.empty()) throw InputError(mismatch);
  if (c.panels.size() != renderer.panels()) throw InputError(s.checkpoint + ": not a valid checkpoint (panels)");
  const std::string wrong = renderer.memory_error(c.panels);
  if (!wrong.empty()) throw InputError(s.checkpoint + ": not a valid checkpoint (" + wrong + ")");
  renderer.restore(c.panels);
  if (report) report->restore(c.report);
  io::remove_stale_partials(std::filesystem::path(s.output).parent_path());
  return c.next_frame;
}

}  // namespace

RunSummary run(const Settings& s) {
  cv::setNumThreads(s.threads > 0 ? s.threads : -1);
  io::set_library_verbosity(s.verbose);
  std::unique_ptr<io::FrameSource> source = open_input(s);
  const io::SourceInfo& info = source->info();
  const LoadedGaze gaze = load_gaze(s, info);
  const std::vector<io::GazeSample>& samples = gaze.samples;
  if (gaze.summary) {  // before the work; the summary line itself comes with the run's (RunSummary)
    if (!s.quiet)
      for (const std::string& n : gaze.summary->notes) std::fprintf(stderr, "eyestream: gaze: %s\n", n.c_str());
    for (const std::string& w : gaze.summary->warnings) std::fprintf(stderr, "eyestream: warning: %s\n", w.c_str());
  }
  TargetRegion(s.target_rect, s.target_mask, cv::Size(info.width, info.height));  // refused before any work
  refuse_before_work(s, info);
  io::SinkOptions sink_options = s.sink;
  sink_options.video.frames_per_second = info.frames_per_second;
  sink_options.png_gamma = s.encoding.gamma;
  std::unique_ptr<io::FrameSink> sink = io::make_sink(s.output, sink_options);
  if (overlap_io(s)) sink = std::make_unique<io::BackgroundSink>(std::move(sink));
  PreviewRenderer renderer(s, info, sink->needs());
  // The set-up's temporaries the pool kept are mostly not the frames'
  // sizes: freed now, they are not added to the first frame's peak.
  release_frame_buffers();
  if (s.verbose) std::fprintf(stderr, "%s: %s\n%s", s.input.c_str(), info.description.c_str(), renderer.describe().c_str());
  const size_t main = renderer.main_panel();
  renderer.set_gaze(samples);
  std::unique_ptr<ReportWriter> report = report_writer(s, renderer);
  if (report && gaze.summary) report->set_gaze(*gaze.summary);
  const std::string settings = run_settings(s, info);
  const std::uint64_t identity = run_identity(settings);
  const std::int64_t resume_from = prepare_checkpoints(s, settings, *sink, renderer, report.get());
  const char* kill_at = std::getenv("EYESTREAM_TEST_KILL_AT_FRAME");  // crash injection for the resume test
  const char* signal_at = std::getenv("EYESTREAM_TEST_SIGNAL_AT_FRAME");  // "N" or "N,SIGNUM": the interrupt tests
  const InterruptGuard interrupts;

  std::optional<io::StagedFile> state_file;  // committed with the other outputs
  RunSummary summary;
  summary.output = s.output;
  Progress progress(info.frame_count, s.progress && !s.quiet, s.progress_every_s, s.progress_file);
  // One frame decoded ahead: decoding (about 28 ms of a 1080p EXR) is far
  // shorter than the eye's frame, and each frame held costs a frame of
  // memory. The eye needs the next frame's time: a file sequence knows it
  // from the file numbers, and two frames are held, the current one and
  // the one being decoded or queued; a video knows it only by decoding, and
  // three are held, the next one taken early for its time. The decoder
  // waits for room before it decodes another.
  // With --end-frame it decodes nothing the run will not take: the last
  // frame is the one before it for a source that knows its frames' times
  // (a file sequence), the one at it for a source that learns them only by
  // decoding (a video or raw stream: that frame is decoded for its time).
  const bool times_known = source->knows_times();  // a property of the source, for the whole sequence
  if (overlap_io(s))
    source = std::make_unique<io::PrefetchSource>(std::move(source), 1,
                                                  s.end_frame > 0 ? s.end_frame - (times_known ? 1 : 0) : -1);
  const std::int64_t first_processed =
      std::max<std::int64_t>(0, s.start_frame - std::int64_t(std::ceil(s.preroll_s * info.frames_per_second)));
  std::optional<io::SceneFrame> current = source->next();
  const std::int64_t skip_to = std::max(first_processed, resume_from);
  while (current && current->index < skip_to) current = source->next();  // before the pre-roll or the checkpoint
  while (current && (s.end_frame == 0 || current->index < s.end_frame)) {
    if (InterruptGuard::received()) {
      summary.interrupted_by = InterruptGuard::received();
      // Where a resumed run would go on: a checkpoint at this frame.
      if (!s.checkpoint.empty() && summary.frames > 0 && sink->commit_so_far()) {
        write_checkpoint(s.checkpoint, {identity, settings, current->index, report ? report->save() : nlohmann::json(),
                                        renderer.save()});
        summary.checkpoint = s.checkpoint;
      }
      break;
    }
    std::optional<io::SceneFrame> next;
    if (!times_known) next = source->next();
    const std::optional<double> next_time = times_known ? source->time_of(current->index + 1)
                                            : next        ? std::optional<double>(next->time_s)
                                                          : std::nullopt;
    const double t1 = next_time ? *next_time : current->time_s + 1.0 / info.frames_per_second;
    const bool written = current->index >= s.start_frame;
    // The eye is handed the only reference to the frame's pixels, and lets
    // go of them after the glare (EyeSimulator::process).
    io::SceneFrame given = *current;
    current->rgb.release();
    const io::DisplayFrame shown = renderer.process(std::move(given), t1);
    const FrameReport& main_report = renderer.report(main);
    if (main_report.nonfinite_pixels > 0 && s.bad_pixels == "fail")
      throw InputError(current->source + ": frame " + std::to_string(current->index) + " has " +
                       std::to_string(main_report.nonfinite_pixels) +
                       " NaN or infinite pixels (--bad-pixels clamp to go on)");
    if (written) sink->write(shown);
    for (size_t i = 0, v = 0; written && report && i < renderer.panels(); ++i)
      if (renderer.spec(i).viewer) report->add(current->index, current->time_s, v++, renderer.report(i));
    if (!s.state_exr.empty() && current->index == s.state_frame)
      state_file.emplace(renderer.eye(main).retina().stage_state(s.state_exr));
    if (written && next_time && s.checkpoint_every > 0 && (current->index + 1 - s.start_frame) % s.checkpoint_every == 0) {
      sink->commit_so_far();  // the frames so far must outlive a crash
      write_checkpoint(s.checkpoint, {identity, settings, current->index + 1, report ? report->save() : nlohmann::json(),
                                      renderer.save()});
    }
    if (kill_at && std::atoll(kill_at) == current->index) std::_Exit(137);
    if (signal_at && std::atoll(signal_at) == current->index)
      std::raise(std::strchr(signal_at, ',') ? std::atoi(std::strchr(signal_at, ',') + 1) : SIGINT);
    summary.nonfinite_pixels += main_report.nonfinite_pixels;
    if (s.verbose) log_frame(*current, main_report);
    summary.frames += written;
    progress.frame_done();
    if (times_known) {
      // The frame is let go before the next is taken (the decoder may then
      // start the one after), and none is decoded past --end-frame.
      const bool last = s.end_frame > 0 && current->index + 1 >= s.end_frame;
      current.reset();
      if (!last) current = source->next();
    } else {
      current = std::move(next);
    }
  }
  if (summary.frames == 0 && summary.interrupted_by) throw Interrupted(summary.interrupted_by);
  if (summary.frames == 0)
    throw InputError(s.input + (s.start_frame > 0 ? ": no frame at or after --start-frame " +
                                                       std::to_string(s.start_frame)
                                                 : std::string(": no frame could be read")));
  // Every output is complete under its temporary name before any is
  // renamed into place: a failure leaves none of them.
  std::vector<io::StagedFile> staged;
  if (report) staged = report->stage();
  sink->finish();
  for (io::StagedFile& f : staged) f.commit();
  if (state_file) state_file->commit();
  progress.finish();
  summary.wall_s = progress.elapsed_s();
  summary.final_adaptation_log = renderer.eye(main).adaptation_log();
  if (gaze.summary) summary.gaze = gaze.summary->line();
  return summary;
}

}  // namespace eyestream::pipeline
