#include "io/staged_file.hpp"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <mutex>
#include <set>
#include <system_error>

#include "io/error.hpp"

namespace eyestream::io {
namespace fs = std::filesystem;

namespace {

std::mutex g_inputs_mutex;
std::set<fs::path>& protected_inputs() {
  static std::set<fs::path> inputs;
  return inputs;
}

fs::path canonical_or_absolute(const fs::path& p) {
  std::error_code ec;
  fs::path c = fs::weakly_canonical(p, ec);
  return ec ? fs::absolute(p) : c;
}

fs::path make_temp_name(const fs::path& final_path) {
  static std::atomic<unsigned> counter{0};
  fs::path dir = final_path.parent_path();
  std::string name =
      "." + final_path.filename().string() + ".partial-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  return dir / name;
}

}  // namespace

void protect_input(const fs::path& path) {
  std::lock_guard<std::mutex> lock(g_inputs_mutex);
  protected_inputs().insert(canonical_or_absolute(path));
}

void check_not_input(const fs::path& path) {
  std::lock_guard<std::mutex> lock(g_inputs_mutex);
  if (protected_inputs().count(canonical_or_absolute(path)))
    throw OutputError(path.string() + ": output would overwrite an input file");
}

fs::path staged_temp_path(const fs::path& final_path, const std::string& tag) {
  return final_path.parent_path() /
         ("." + final_path.filename().string() + ".partial-" + std::to_string(::getpid()) + "-" + tag);
}

StagedFile::StagedFile(fs::path final_path, const std::string& tag) : StagedFile(std::move(final_path)) {
  temp_ = staged_temp_path(final_, tag);
}

StagedFile::StagedFile(fs::path final_path) : final_(std::move(final_path)) {
  check_not_input(final_);
  fs::path dir = final_.parent_path();
  std::error_code ec;
  if (!dir.empty() && !fs::exists(dir, ec)) {
    fs::create_directories(dir, ec);
    if (ec) throw OutputError(dir.string() + ": cannot create output folder: " + ec.message());
  }
  temp_ = make_temp_name(final_);
}

StagedFile::StagedFile(StagedFile&& other) noexcept
    : final_(std::move(other.final_)), temp_(std::move(other.temp_)), done_(other.done_) {
  other.done_ = true;
}

StagedFile::~StagedFile() {
  if (!done_) {
    std::error_code ec;
    fs::remove(temp_, ec);
  }
}

void StagedFile::commit() {
  std::error_code ec;
  fs::rename(temp_, final_, ec);
  if (ec) throw OutputError(final_.string() + ": cannot move finished output into place: " + ec.message());
  done_ = true;
}

void write_all(const StagedFile& file, const std::vector<unsigned char>& bytes) {
  std::ofstream out(file.temp_path(), std::ios::binary | std::ios::trunc);
  if (!out) throw OutputError(file.final_path().string() + ": cannot open for writing: " + std::strerror(errno));
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  out.flush();
  if (!out) throw OutputError(file.final_path().string() + ": write failed (disk full?)");
}

int remove_stale_partials(const fs::path& dir) {
  int removed = 0;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir.empty() ? fs::path(".") : dir, ec)) {
    const std::string name = entry.path().filename().string();
    const size_t at = name.rfind(".partial-");
    if (name.empty() || name[0] != '.' || at == std::string::npos) continue;
    const long pid = std::strtol(name.c_str() + at + 9, nullptr, 10);
    if (pid <= 0 || pid == ::getpid() || ::kill(pid_t(pid), 0) == 0 || errno != ESRCH) continue;
    removed += fs::remove(entry.path(), ec) ? 1 : 0;
  }
  return removed;
}

}  // namespace eyestream::io
