#include "pipeline/bench/peers/bench_peers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "pipeline/bench/bench_case.hpp"
#include "pipeline/bench/peers/peer_program.hpp"
#include "pipeline/bench/peers/peer_timings.hpp"
#include "pipeline/bench/scratch_folder.hpp"
#include "pipeline/eye/glare_stage.hpp"
#include "retina/luminance.hpp"

namespace eyestream::pipeline {

namespace {

constexpr double kPattanaikTarget = 12.0, kFogGlowTarget = 100.0;
constexpr int kFogGlowRuns = 3;

// The retinal image of `frame` by `preset`'s glare stage, every pixel's
// light spread (no skipping), for a viewer adapted to the frame's mean
// luminance, with no surround.
cv::Mat glare_of(const std::string& preset, const std::string& flare_model, const io::SceneFrame& frame,
                 const io::SourceInfo& info) {
  GlareStage stage(compile_plan(preset_settings(preset, false, flare_model), info));
  const cv::Scalar mean = cv::mean(frame.rgb);
  const double y = retina::photopic_luminance(cv::Vec3f(float(mean[0]), float(mean[1]), float(mean[2])));
  return stage.apply(frame.rgb, std::log10(std::max(y, 1e-4)), 0.0);
}

// Per channel, the difference of the total light of `fast`'s glare and
// `reference`'s, relative to the light the reference moved (what left the
// pixels that lost light: the light both engines keep in place is left
// out, so the error is the scattered light's); the largest channel.
double energy_error(const io::SceneFrame& frame, const io::SourceInfo& info, const std::string& flare_model) {
  const cv::Mat fast = glare_of("fast", flare_model, frame, info);
  const cv::Mat exact = glare_of("reference", flare_model, frame, info);
  const cv::Scalar difference = cv::sum(fast) - cv::sum(exact);
  const cv::Scalar moved = cv::sum(cv::max(frame.rgb - exact, 0.0));
  double worst = 0.0;
  for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(difference[c]) / std::max(moved[c], 1e-30));
  return worst;
}

PeerRow row(const std::string& peer, const std::string& scene, const std::string& size, double target) {
  PeerRow r;
  r.peer = peer, r.scene = scene, r.size = size, r.target = target;
  return r;
}

void peers_on(const std::string& scene_name, const std::string& size, const BenchRequest& q,
              std::vector<PeerRow>& rows) {
  const cv::Size wh = parse_frame_size(size);
  const ScratchFolder dir;
  const BenchScene scene = load_bench_scene_in(dir.path(), scene_name, wh.width, wh.height, q.frames);
  const BenchCase fast = run_bench_case(scene, preset_settings("fast", false, q.flare_model));

  PeerRow pattanaik = row("pfstmo_pattanaik00 -t", scene_name, size, kPattanaikTarget);
  pattanaik.eyestream_ms = fast.wall_ms;
  const std::string pfsinexr = find_on_path("pfsinexr"), pfstmo = find_on_path("pfstmo_pattanaik00");
  if (pfsinexr.empty() || pfstmo.empty()) {
    pattanaik.skipped = "not installed (Debian: pfstools, pfstmo)";
  } else {
    const PeerTiming t = time_pattanaik(pfsinexr, pfstmo, dir.path() / "frames", int(scene.frames.size()),
                                        scene.info.frames_per_second, dir.path());
    pattanaik.peer_ms = t.ms_per_frame;
    pattanaik.floor_ms = t.floor_ms_per_frame;
    pattanaik.skipped = t.failure.empty() ? "" : "failed: " + t.failure;
  }
  rows.push_back(pattanaik);

  PeerRow fog = row("blender fog glow", scene_name, size, kFogGlowTarget);
  fog.eyestream_ms = fast.stage_ms.glare_ms;
  const std::string blender = find_on_path("blender");
  if (blender.empty()) {
    fog.skipped = "not installed (Debian: blender)";
  } else {
    const size_t middle = scene.frames.size() / 2;
    char name[32];
    std::snprintf(name, sizeof name, "%05zu.exr", middle);
    const PeerTiming t = time_fog_glow(blender, dir.path() / "frames" / name, kFogGlowRuns, dir.path());
    fog.peer_ms = t.ms_per_frame;
    fog.skipped = t.failure.empty() ? "" : "failed: " + t.failure;
    if (t.failure.empty()) fog.energy_error = energy_error(scene.frames[middle], scene.info, q.flare_model);
  }
  rows.push_back(fog);
  if (!q.quiet) {
    for (size_t i = rows.size() - 2; i < rows.size(); ++i) {
      if (rows[i].skipped.empty())
        std::fprintf(stderr, "bench: %s %s %s: %.1f ms/frame\n", scene_name.c_str(), size.c_str(),
                     rows[i].peer.c_str(), rows[i].peer_ms);
      else
        std::fprintf(stderr, "bench: %s %s %s: %s\n", scene_name.c_str(), size.c_str(), rows[i].peer.c_str(),
                     rows[i].skipped.c_str());
    }
  }
}

}  // namespace

std::vector<PeerRow> run_peers(const BenchRequest& q) {
  std::vector<PeerRow> rows;
  for (const std::string& scene : split_list(q.scene))
    for (const std::string& size : split_list(q.sizes)) peers_on(scene, size, q, rows);
  return rows;
}

std::string peers_table(const std::vector<PeerRow>& rows) {
  std::ostringstream o;
  char line[512];
  std::snprintf(line, sizeof line, "%-22s %-11s %-6s %10s %9s %10s %8s %7s %7s  %s\n", "peer", "scene", "size",
                "peer_ms", "io_ms", "eyestream", "ratio", "target", "energy", "eyestream measured");
  o << line;
  for (const PeerRow& r : rows) {
    const bool glare = r.peer.rfind("blender", 0) == 0;
    const char* what = glare ? "fast's glare stage (stage time)" : "fast, every effect: process() and encoding";
    if (!r.skipped.empty()) {
      std::snprintf(line, sizeof line, "%-22s %-11s %-6s %s\n", r.peer.c_str(), r.scene.c_str(), r.size.c_str(),
                    ("skipped: " + r.skipped).c_str());
    } else {
      char energy[16] = "-", floor[16] = "-";
      if (r.energy_error >= 0.0) std::snprintf(energy, sizeof energy, "%.3f%%", 100.0 * r.energy_error);
      if (r.floor_ms >= 0.0) std::snprintf(floor, sizeof floor, "%.1f", r.floor_ms);
      std::snprintf(line, sizeof line, "%-22s %-11s %-6s %10.1f %9s %10.1f %7.1fx %6.0fx %7s  %s\n", r.peer.c_str(),
                    r.scene.c_str(), r.size.c_str(), r.peer_ms, floor, r.eyestream_ms,
                    r.eyestream_ms > 0 ? r.peer_ms / r.eyestream_ms : 0.0, r.target, energy, what);
    }
    o << line;
  }
  return o.str();
}

}  // namespace eyestream::pipeline
