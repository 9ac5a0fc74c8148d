#include "pipeline/bench/bench_command.hpp"

#include <cstdio>
#include <optional>
#include <sstream>

#include "io/error.hpp"
#include "io/staged_file.hpp"
#include "pipeline/settings/quality_presets.hpp"
#include "samples/scene.hpp"

namespace eyestream::pipeline {

namespace {

BenchRow row_of(const std::string& scene, const std::string& size, const std::string& preset, bool skip,
                BenchCase figures, bool quiet) {
  figures.shown.clear();
  BenchRow r{scene, size, preset, skip, "", std::move(figures), {}};
  if (!quiet)
    std::fprintf(stderr, "bench: %s %s %s%s: %.1f ms/frame\n", scene.c_str(), size.c_str(), preset.c_str(),
                 skip ? "" : " --no-skip", r.figures.filter_ms);
  return r;
}

// Each preset on `scene` against the reference (run first if asked for).
void presets_on(const BenchScene& scene, const std::string& size, const std::vector<std::string>& presets,
                const BenchRequest& q, std::vector<BenchRow>& rows) {
  const bool quiet = q.quiet;
  std::optional<BenchCase> reference;
  for (const std::string& p : presets) {
    BenchCase c = run_bench_case(scene, preset_settings(p, true, q.flare_model));
    ReferenceError e;
    if (p == "reference") reference = c;
    if (reference && p != "reference") e = error_against(*reference, c);
    rows.push_back(row_of(scene.name, size, p, true, std::move(c), quiet));
    rows.back().error = e;
    rows.back().against = reference ? "reference" : "";
  }
}

// Balanced with and without skipping: the cost of a frame that needs
// little against one that needs everything, and what skipping changes.
void skip_study(const BenchScene& scene, const std::string& size, const BenchRequest& q, std::vector<BenchRow>& rows) {
  const bool quiet = q.quiet;
  const BenchCase off = run_bench_case(scene, preset_settings("balanced", false, q.flare_model));
  BenchCase on = run_bench_case(scene, preset_settings("balanced", true, q.flare_model));
  const ReferenceError e = error_against(off, on);
  rows.push_back(row_of(scene.name, size, "balanced", false, off, quiet));
  rows.push_back(row_of(scene.name, size, "balanced", true, std::move(on), quiet));
  rows.back().error = e;
  rows.back().against = "balanced --no-skip";
}

std::string fixed(double v, int decimals) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.*f", decimals, v);
  return buf;
}

}  // namespace

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

Settings preset_settings(const std::string& preset, bool skip, const std::string& flare_model) {
  Settings s;
  apply_quality_preset(preset, s);
  s.skip = skip;
  s.flare_model = flare_model;
  return s;
}

cv::Size parse_frame_size(const std::string& text) {
  if (text == "720p") return {1280, 720};
  if (text == "1080p") return {1920, 1080};
  if (text == "4k" || text == "2160p") return {3840, 2160};
  int w = 0, h = 0;
  char end = 0;
  if (std::sscanf(text.c_str(), "%dx%d%c", &w, &h, &end) == 2 && w >= 16 && h >= 16 && w <= 8192 && h <= 8192)
    return {w, h};
  throw UsageError("--sizes: '" + text + "' is not 720p, 1080p, 4k or WxH (16 to 8192)");
}

std::vector<BenchRow> run_bench(const BenchRequest& q) {
  if (q.frames < 2) throw UsageError("--frames must be at least 2");
  if (q.flare_model != "drawn" && q.flare_model != "wave")
    throw UsageError("--flare-model must be drawn or wave, not '" + q.flare_model + "'");
  const std::vector<std::string> sizes = split_list(q.sizes), presets = split_list(q.presets);
  if (sizes.empty() || presets.empty()) throw UsageError("--sizes and --presets need at least one entry");
  for (const std::string& p : presets) preset_settings(p, true);  // names checked before any work
  for (const std::string& s : sizes) parse_frame_size(s);
  const std::vector<std::string> scenes = split_list(q.scene);
  if (scenes.empty()) throw UsageError("--scene needs at least one scene");
  for (const std::string& name : scenes) samples::find_scene(name);  // names checked before any work
  std::vector<BenchRow> rows;
  for (const std::string& name : scenes)
    for (const std::string& size : sizes) {
      const cv::Size wh = parse_frame_size(size);
      presets_on(load_bench_scene(name, wh.width, wh.height, q.frames), size, presets, q, rows);
    }
  for (const std::string& size : sizes) {
    const cv::Size wh = parse_frame_size(size);
    if (q.skip_study && &size == &sizes.front()) {
      const BenchScene scene = load_bench_scene(scenes.front(), wh.width, wh.height, q.frames);
      // A dim still frame: the headlights scene with its lamps at half the
      // display peak, so nothing needs glare and the retina rests.
      const BenchScene dim = load_bench_scene("headlights", wh.width, wh.height, q.frames, 50.0);
      skip_study(dim, size, q, rows);
      skip_study(scene, size, q, rows);
    }
  }
  return rows;
}

std::string bench_table(const std::vector<BenchRow>& rows) {
  std::ostringstream o;
  char line[400];
  std::snprintf(line, sizeof(line), "%-11s %-6s %-9s %-4s %9s %7s %7s %7s %7s %7s %7s %7s %7s %7s %6s %6s %8s  %s\n",
                "scene", "size", "preset", "skip", "ms/frame", "fps", "glare", "adapt", "retina", "mesop", "after",
                "encode", "setup_s", "MiB", "dE99", "dEmax", "state", "against");
  o << line;
  for (const BenchRow& r : rows) {
    const BenchCase& f = r.figures;
    const bool err = !r.against.empty();
    std::snprintf(line, sizeof(line),
                  "%-11s %-6s %-9s %-4s %9.1f %7.2f %7.1f %7.1f %7.1f %7.1f %7.1f %7.1f %7.2f %7.0f %6s %6s %8s  %s\n",
                  r.scene.c_str(), r.size.c_str(), r.preset.c_str(), r.skip ? "on" : "off", f.filter_ms,
                  f.filter_ms > 0 ? 1000.0 / f.filter_ms : 0.0, f.stage_ms.glare_ms, f.stage_ms.adaptation_ms,
                  f.stage_ms.retina_ms, f.stage_ms.mesopic_ms, f.stage_ms.afterimage_ms, f.encode_ms, f.setup_s,
                  f.memory_mib, err ? fixed(r.error.de_p99, 2).c_str() : "-", err ? fixed(r.error.de_max, 2).c_str() : "-",
                  err ? fixed(r.error.state, 5).c_str() : "-", err ? r.against.c_str() : "-");
    o << line;
  }
  return o.str();
}

void write_bench_csv(const std::vector<BenchRow>& rows, const std::string& path) {
  std::string text =
      "scene,size,preset,skip,frames,filter_ms,fps,glare_ms,adaptation_ms,retina_ms,mesopic_ms,afterimage_ms,"
      "encode_ms,setup_s,memory_mib,glare_frames,retina_frames,afterimage_frames,mesopic_frames,acuity_frames,"
      "de2000_p99,de2000_max,state_error,against,rest_frames,rest_ms\n";
  for (const BenchRow& r : rows) {
    const BenchCase& f = r.figures;
    const bool err = !r.against.empty();
    std::ostringstream o;
    o.precision(6);
    o << r.scene << ',' << r.size << ',' << r.preset << ',' << (r.skip ? "on" : "off") << ',' << f.frames << ','
      << f.filter_ms << ',' << (f.filter_ms > 0 ? 1000.0 / f.filter_ms : 0.0) << ',' << f.stage_ms.glare_ms << ','
      << f.stage_ms.adaptation_ms << ',' << f.stage_ms.retina_ms << ',' << f.stage_ms.mesopic_ms << ','
      << f.stage_ms.afterimage_ms << ',' << f.encode_ms << ',' << f.setup_s << ',' << f.memory_mib << ','
      << f.glare_frames << ',' << f.retina_frames << ',' << f.afterimage_frames << ',' << f.mesopic_frames << ','
      << f.acuity_frames << ',';
    if (err) o << r.error.de_p99 << ',' << r.error.de_max << ',' << r.error.state << ',' << r.against;
    else o << ",,,";
    o << ',' << f.rest_frames << ',' << f.rest_ms;
    text += o.str() + "\n";
  }
  io::StagedFile file(path);
  io::write_all(file, std::vector<unsigned char>(text.begin(), text.end()));
  file.commit();
}

}  // namespace eyestream::pipeline
