#include "pipeline/checkpoint.hpp"

#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

#include "io/error.hpp"
#include "io/staged_file.hpp"
#include "pipeline/parameter.hpp"

namespace eyestream::pipeline {

namespace {

constexpr char kMagic[] = "EYESTREAM-CHECKPOINT-1\n";

std::uint64_t fnv1a(const std::string& text) {
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ULL;
  return h;
}

void put_u64(std::string& out, std::uint64_t v) { out.append(reinterpret_cast<const char*>(&v), sizeof(v)); }

std::uint64_t get_u64(std::istream& in, const std::string& path) {
  std::uint64_t v = 0;
  if (!in.read(reinterpret_cast<char*>(&v), sizeof(v))) throw InputError(path + ": checkpoint is truncated");
  return v;
}

void put_mat(std::string& out, const cv::Mat& m) {
  put_u64(out, std::uint64_t(m.empty() ? -1 : m.type()));
  put_u64(out, std::uint64_t(m.rows));
  put_u64(out, std::uint64_t(m.cols));
  if (m.empty()) return;
  const cv::Mat c = m.isContinuous() ? m : m.clone();
  out.append(reinterpret_cast<const char*>(c.data), c.total() * c.elemSize());
}

cv::Mat get_mat(std::istream& in, const std::string& path) {
  const std::int64_t type = std::int64_t(get_u64(in, path));
  const std::uint64_t rows = get_u64(in, path), cols = get_u64(in, path);
  if (type < 0) return cv::Mat();
  if (rows > 65536 || cols > 65536 || type > CV_64FC4) throw InputError(path + ": not a valid checkpoint");
  cv::Mat m(static_cast<int>(rows), static_cast<int>(cols), static_cast<int>(type));
  if (!in.read(reinterpret_cast<char*>(m.data), std::streamsize(m.total() * m.elemSize())))
    throw InputError(path + ": checkpoint is truncated");
  return m;
}

}  // namespace

std::uint64_t run_identity(const Settings& s, const io::SourceInfo& source) {
  Settings copy = s;
  const std::set<std::string> ignored = {"threads", "progress", "verbose", "print-plan",
                                         "checkpoint", "checkpoint-every", "resume"};
  std::ostringstream text;
  const ParamSet params = run_parameters(copy);
  for (const Param& p : params.params())
    if (!ignored.count(p.name)) text << p.name << '=' << ParamSet::value_text(p) << '\n';
  text << "input=" << s.input << "\ngaze=" << s.gaze << "\noutput=" << s.output << "\nsize=" << source.width << 'x'
       << source.height << "\nframes=" << source.frame_count << '\n';
  return fnv1a(text.str());
}

void write_checkpoint(const std::string& path, const Checkpoint& c) {
  nlohmann::json header = {{"identity", c.identity}, {"next_frame", c.next_frame}, {"report", c.report}};
  nlohmann::json panels = nlohmann::json::array();
  for (const EyeMemory& m : c.panels)
    panels.push_back({{"adaptation_log", m.adaptation_log ? nlohmann::json(*m.adaptation_log) : nlohmann::json()},
                      {"pupil_mm", m.pupil_mm ? nlohmann::json(*m.pupil_mm) : nlohmann::json()},
                      {"retina_started", m.retina_started},
                      {"matrices", m.retina.size()}});
  header["panels"] = panels;
  const std::string json = header.dump();
  std::string bytes = kMagic;
  put_u64(bytes, json.size());
  bytes += json;
  for (const EyeMemory& m : c.panels)
    for (const cv::Mat& mat : m.retina) put_mat(bytes, mat);
  io::StagedFile file(path);
  io::write_all(file, std::vector<unsigned char>(bytes.begin(), bytes.end()));
  file.commit();
}

Checkpoint read_checkpoint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": no checkpoint to resume from");
  char magic[sizeof(kMagic) - 1];
  if (!in.read(magic, sizeof(magic)) || std::memcmp(magic, kMagic, sizeof(magic)) != 0)
    throw InputError(path + ": not an eyestream checkpoint");
  const std::uint64_t length = get_u64(in, path);
  if (length > (1ULL << 32)) throw InputError(path + ": not a valid checkpoint");
  std::string json(length, '\0');
  if (!in.read(json.data(), std::streamsize(length))) throw InputError(path + ": checkpoint is truncated");
  Checkpoint c;
  try {
    const nlohmann::json header = nlohmann::json::parse(json);
    c.identity = header.at("identity").get<std::uint64_t>();
    c.next_frame = header.at("next_frame").get<std::int64_t>();
    c.report = header.at("report");
    for (const nlohmann::json& p : header.at("panels")) {
      EyeMemory m;
      if (!p.at("adaptation_log").is_null()) m.adaptation_log = p.at("adaptation_log").get<double>();
      if (!p.at("pupil_mm").is_null()) m.pupil_mm = p.at("pupil_mm").get<double>();
      m.retina_started = p.at("retina_started").get<bool>();
      m.retina.resize(p.at("matrices").get<size_t>());
      c.panels.push_back(m);
    }
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path + ": not a valid checkpoint (" + e.what() + ")");
  }
  for (EyeMemory& m : c.panels)
    for (cv::Mat& mat : m.retina) mat = get_mat(in, path);
  return c;
}

}  // namespace eyestream::pipeline
