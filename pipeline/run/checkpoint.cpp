#include "pipeline/run/checkpoint.hpp"

#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

#include "io/error.hpp"
#include "io/staged_file.hpp"
#include "pipeline/settings/parameter.hpp"

namespace eyestream::pipeline {

namespace {

constexpr char kMagic[] = "EYESTREAM-CHECKPOINT-2\n";
constexpr size_t kMaxPanels = 64, kMaxMatrices = 16;

std::uint64_t fnv1a(const char* data, size_t size) {
  std::uint64_t h = 1469598103934665603ULL;
  for (size_t i = 0; i < size; ++i) h = (h ^ static_cast<unsigned char>(data[i])) * 1099511628211ULL;
  return h;
}

std::uint64_t fnv1a(const std::string& text) { return fnv1a(text.data(), text.size()); }

void put_u64(std::string& out, std::uint64_t v) { out.append(reinterpret_cast<const char*>(&v), sizeof(v)); }

// Reads from a checkpoint's bytes, refusing to run past their end.
struct Reader {
  const std::string& bytes;
  const std::string& path;
  size_t at = 0;
  const char* take(size_t n) {
    if (n > bytes.size() - at) throw InputError(path + ": checkpoint is truncated");
    const char* p = bytes.data() + at;
    at += n;
    return p;
  }
  std::uint64_t u64() {
    std::uint64_t v = 0;
    std::memcpy(&v, take(sizeof(v)), sizeof(v));
    return v;
  }
};

void put_mat(std::string& out, const cv::Mat& m) {
  put_u64(out, std::uint64_t(m.empty() ? -1 : m.type()));
  put_u64(out, std::uint64_t(m.rows));
  put_u64(out, std::uint64_t(m.cols));
  if (m.empty()) return;
  const cv::Mat c = m.isContinuous() ? m : m.clone();
  out.append(reinterpret_cast<const char*>(c.data), c.total() * c.elemSize());
}

cv::Mat get_mat(Reader& in) {
  const std::int64_t type = std::int64_t(in.u64());
  const std::uint64_t rows = in.u64(), cols = in.u64();
  if (type < 0) return cv::Mat();
  if (rows == 0 || cols == 0 || rows > 65536 || cols > 65536 || type > CV_64FC4)
    throw InputError(in.path + ": not a valid checkpoint (a state matrix of " + std::to_string(rows) + "x" +
                     std::to_string(cols) + ")");
  const std::uint64_t size = rows * cols * std::uint64_t(CV_ELEM_SIZE(static_cast<int>(type)));
  const char* data = in.take(size_t(size));  // refuses a size the file does not hold, before allocating
  cv::Mat m(static_cast<int>(rows), static_cast<int>(cols), static_cast<int>(type));
  std::memcpy(m.data, data, size_t(size));
  return m;
}

// The first line in which two settings texts differ, as "a" vs "b".
std::string first_difference(const std::string& a, const std::string& b) {
  std::istringstream sa(a), sb(b);
  std::string la, lb;
  while (true) {
    const bool more_a = bool(std::getline(sa, la)), more_b = bool(std::getline(sb, lb));
    if (!more_a && !more_b) return "";
    if (!more_a || !more_b || la != lb) return (more_a ? la : "(nothing)") + ", this run has " + (more_b ? lb : "(nothing)");
  }
}

}  // namespace

std::string run_settings(const Settings& s, const io::SourceInfo& source) {
  Settings copy = s;
  // What changes how a run reports or where it writes, not what it computes.
  const std::set<std::string> ignored = {"threads",    "progress",         "verbose", "print-plan",
                                         "max-pixels", "checkpoint",       "checkpoint-every", "resume",
                                         "quiet",      "progress-every",   "progress-file", "overwrite"};
  std::ostringstream text;
  const ParamSet params = run_parameters(copy);
  for (const Param& p : params.params())
    if (!ignored.count(p.name)) text << p.name << '=' << ParamSet::value_text(p) << '\n';
  text << "input=" << s.input << "\ngaze=" << s.gaze << "\noutput=" << s.output << "\nsize=" << source.width << 'x'
       << source.height << "\nframes=" << source.frame_count << '\n';
  return text.str();
}

std::uint64_t run_identity(const std::string& settings) { return fnv1a(settings); }

std::string checkpoint_mismatch(const std::string& path, const Checkpoint& c, const std::string& settings) {
  if (c.identity == run_identity(settings)) return "";
  const std::string diff = first_difference(c.settings, settings);
  return path + ": written by a run with other settings or input (" + (diff.empty() ? "unknown" : diff) +
         "); resume with the same command";
}

void write_checkpoint(const std::string& path, const Checkpoint& c) {
  nlohmann::json header = {
      {"identity", c.identity}, {"settings", c.settings}, {"next_frame", c.next_frame}, {"report", c.report}};
  nlohmann::json panels = nlohmann::json::array();
  for (const EyeMemory& m : c.panels)
    panels.push_back({{"adaptation_log", m.adaptation_log ? nlohmann::json(*m.adaptation_log) : nlohmann::json()},
                      {"pupil_mm", m.pupil_mm ? nlohmann::json(*m.pupil_mm) : nlohmann::json()},
                      {"retina_started", m.retina_started},
                      {"matrices", m.retina.size()}});
  header["panels"] = panels;
  const std::string json = header.dump();
  std::string body;
  put_u64(body, json.size());
  body += json;
  for (const EyeMemory& m : c.panels)
    for (const cv::Mat& mat : m.retina) put_mat(body, mat);
  // The magic, a checksum (FNV-1a) of everything after it, then the body.
  std::string bytes = kMagic;
  put_u64(bytes, fnv1a(body));
  bytes += body;
  io::StagedFile file(path);
  io::write_all(file, std::vector<unsigned char>(bytes.begin(), bytes.end()));
  file.commit();
}

Checkpoint read_checkpoint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": no checkpoint to resume from");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t magic = sizeof(kMagic) - 1;
  if (bytes.size() < magic || bytes.compare(0, magic, kMagic) != 0) throw InputError(path + ": not an eyestream checkpoint");
  Reader r{bytes, path, magic};
  const std::uint64_t checksum = r.u64();
  if (checksum != fnv1a(bytes.data() + r.at, bytes.size() - r.at))
    throw InputError(path + ": checkpoint is corrupt (its checksum does not match its contents)");
  const std::uint64_t length = r.u64();
  const std::string json(r.take(size_t(std::min<std::uint64_t>(length, bytes.size()))), size_t(length));
  Checkpoint c;
  try {
    const nlohmann::json header = nlohmann::json::parse(json);
    c.identity = header.at("identity").get<std::uint64_t>();
    c.settings = header.at("settings").get<std::string>();
    c.next_frame = header.at("next_frame").get<std::int64_t>();
    c.report = header.at("report");
    if (header.at("panels").size() > kMaxPanels) throw InputError(path + ": not a valid checkpoint (too many panels)");
    for (const nlohmann::json& p : header.at("panels")) {
      EyeMemory m;
      if (!p.at("adaptation_log").is_null()) m.adaptation_log = p.at("adaptation_log").get<double>();
      if (!p.at("pupil_mm").is_null()) m.pupil_mm = p.at("pupil_mm").get<double>();
      m.retina_started = p.at("retina_started").get<bool>();
      const size_t count = p.at("matrices").get<size_t>();
      if (count > kMaxMatrices) throw InputError(path + ": not a valid checkpoint (" + std::to_string(count) + " matrices)");
      m.retina.resize(count);
      c.panels.push_back(m);
    }
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path + ": not a valid checkpoint (" + e.what() + ")");
  }
  for (EyeMemory& m : c.panels)
    for (cv::Mat& mat : m.retina) mat = get_mat(r);
  if (r.at != bytes.size()) throw InputError(path + ": not a valid checkpoint (bytes after its end)");
  return c;
}

}  // namespace eyestream::pipeline
