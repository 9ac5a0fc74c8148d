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
cv::Mat glare_of(const std::string& preset, const io::SceneFrame& frame, const io::SourceInfo& info) {
  GlareStage stage(compile_plan(preset_settings(preset, false), info));
  const cv::Scalar mean = cv::mean(frame.rgb);
  const double y = retina::photopic_luminance(cv::Vec3f(float(mean[0]), float(mean[1]), float(mean[2])));
  return stage.apply(frame.rgb, std::log10(std::max(y, 1e-4)), 0.0);
}

// The largest relative difference over the channels of the total light
// of `fast`'s glare and `reference`'s.
double energy_error(const io::SceneFrame& frame, const io::SourceInfo& info) {
  const cv::Scalar fast = cv::sum(glare_of("fast", frame, info));
  const cv::Scalar exact = cv::sum(glare_of("reference", frame, info));
  double worst = 0.0;
  for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(fast[c] - exact[c]) / std::max(exact[c], 1e-30));
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
  pattanaik.eyestream_ms = fast.filter_ms + fast.encode_ms;
  const std::string pfsinexr = find_on_path("pfsinexr"), pfstmo = find_on_path("pfstmo_pattanaik00");
  if (pfsinexr.empty() || pfstmo.empty()) {
    pattanaik.skipped = "not installed (Debian: pfstools, pfstmo)";
  } else {
    const PeerTiming t = time_pattanaik(pfsinexr, pfstmo, dir.path() / "frames", int(scene.frames.size()),
                                        scene.info.frames_per_second, dir.path());
    pattanaik.peer_ms = t.ms_per_frame;
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
    fog.energy_error = energy_error(scene.frames[middle], scene.info);
  }
  rows.push_back(fog);
  if (!q.quiet)
    for (size_t i = rows.size() - 2; i < rows.size(); ++i)
      if (rows[i].skipped.empty())
        std::fprintf(stderr, "bench: %s %s %s: %.1f ms/frame\n", scene_name.c_str(), size.c_str(),
                     rows[i].peer.c_str(), rows[i].peer_ms);
      else
        std::fprintf(stderr, "bench: %s %s %s: %s\n", scene_name.c_str(), size.c_str(), rows[i].peer.c_str(),
                     rows[i].skipped.c_str());
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
  std::snprintf(line, sizeof line, "%-22s %-11s %-6s %10s %10s %8s %7s %7s  %s\n", "peer", "scene", "size", "peer_ms",
                "eyestream", "ratio", "target", "energy", "eyestream measured");
  o << line;
  for (const PeerRow& r : rows) {
    const bool glare = r.energy_error >= 0.0;
    const char* what = glare ? "fast's glare stage" : "fast, every effect, filter and encoding";
    if (!r.skipped.empty()) {
      std::snprintf(line, sizeof line, "%-22s %-11s %-6s %s\n", r.peer.c_str(), r.scene.c_str(), r.size.c_str(),
                    ("skipped: " + r.skipped).c_str());
    } else {
      char energy[16] = "-";
      if (glare) std::snprintf(energy, sizeof energy, "%.3f%%", 100.0 * r.energy_error);
      std::snprintf(line, sizeof line, "%-22s %-11s %-6s %10.1f %10.1f %7.1fx %6.0fx %7s  %s\n", r.peer.c_str(),
                    r.scene.c_str(), r.size.c_str(), r.peer_ms, r.eyestream_ms,
                    r.eyestream_ms > 0 ? r.peer_ms / r.eyestream_ms : 0.0, r.target, energy, what);
    }
    o << line;
  }
  return o.str();
}

}  // namespace eyestream::pipeline
