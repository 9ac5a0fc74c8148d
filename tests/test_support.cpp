#include "tests/test_support.hpp"

#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace eyestream::test {
namespace fs = std::filesystem;

ScratchDir::ScratchDir() {
  static std::atomic<int> counter{0};
  path_ =
      fs::temp_directory_path() / ("eyestream-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  fs::remove_all(path_);
  fs::create_directories(path_);
}

ScratchDir::~ScratchDir() {
  std::error_code ec;
  fs::remove_all(path_, ec);
}

CommandResult run_eyestream(const std::string& args) {
  const std::string command = std::string(EYESTREAM_BINARY) + " " + args + " 2>&1";
  CommandResult result;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buf{};
  size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) result.output.append(buf.data(), n);
  const int status = ::pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string first_differing_png(const fs::path& a, const fs::path& b, int frames) {
  for (int k = 0; k < frames; ++k) {
    char name[16];
    std::snprintf(name, sizeof(name), "%05d.png", k);
    if (read_bytes((a / name).string()) != read_bytes((b / name).string())) return name;
  }
  return "";
}

int count_entries(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return 0;
  int n = 0;
  for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator(); it.increment(ec)) ++n;
  return n;
}

pipeline::Plan plan_for(const pipeline::Settings& settings, int width, int height, double fps) {
  io::SourceInfo info;
  info.width = width;
  info.height = height;
  info.frames_per_second = fps;
  return pipeline::compile_plan(settings, info);
}

std::vector<float> openexr_channel(const std::string& path, const std::string& name) {
  Imf::InputFile file(path.c_str());
  const Imath::Box2i dw = file.header().dataWindow();
  const size_t w = size_t(dw.max.x - dw.min.x + 1), h = size_t(dw.max.y - dw.min.y + 1);
  std::vector<float> v(w * h);
  Imf::FrameBuffer fb;
  fb.insert(name, Imf::Slice::Make(Imf::FLOAT, v.data(), dw, sizeof(float), sizeof(float) * w));
  file.setFrameBuffer(fb);
  file.readPixels(dw.min.y, dw.max.y);
  return v;
}

cv::Mat constant_frame(int width, int height, const cv::Vec3f& rgb) {
  return cv::Mat(height, width, CV_32FC3, cv::Scalar(rgb[0], rgb[1], rgb[2]));
}

std::vector<std::string> csv_fields(const std::string& row) {
  std::vector<std::string> out;
  size_t start = 0;
  for (size_t comma = row.find(','); comma != std::string::npos; comma = row.find(',', start)) {
    out.push_back(row.substr(start, comma - start));
    start = comma + 1;
  }
  out.push_back(row.substr(start));
  return out;
}

std::vector<std::map<std::string, std::string>> csv_rows(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> names = csv_fields(line);
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    const std::vector<std::string> fields = csv_fields(line);
    std::map<std::string, std::string>& r = rows.emplace_back();
    for (size_t i = 0; i < names.size() && i < fields.size(); ++i) r[names[i]] = fields[i];
  }
  return rows;
}

}  // namespace eyestream::test
