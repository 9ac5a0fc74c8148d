#include "pipeline/bench/peers/peer_program.hpp"

#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace eyestream::pipeline {

namespace {

constexpr const char* kTimeout = "/usr/bin/timeout";  // coreutils
constexpr int kTimeoutSeconds = 1800;
constexpr size_t kOutputKept = 64 * 1024;

}  // namespace

std::string find_on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::stringstream folders(path ? path : "");
  for (std::string folder; std::getline(folders, folder, ':');) {
    if (folder.empty()) continue;
    const std::string candidate = folder + "/" + name;
    std::error_code ec;
    if (std::filesystem::is_regular_file(candidate, ec) && ::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return "";
}

ProgramRun run_program(const std::string& command) {
  ProgramRun run;
  const auto start = std::chrono::steady_clock::now();
  // coreutils' timeout ends a peer that hangs (and kills it 10 s later if
  // it does not end); only the output's last kOutputKept bytes are kept.
  const bool timed = ::access(kTimeout, X_OK) == 0;
  const std::string line = timed ? std::string(kTimeout) + " -k 10 " + std::to_string(kTimeoutSeconds) +
                                       " /bin/sh -c " + shell_quoted(command)
                                 : command;
  FILE* pipe = ::popen(("exec 2>&1 </dev/null; " + line).c_str(), "r");
  if (!pipe) return run;
  std::array<char, 4096> buf{};
  for (size_t n; (n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0;) {
    run.output.append(buf.data(), n);
    if (run.output.size() > 2 * kOutputKept) run.output.erase(0, run.output.size() - kOutputKept);
  }
  const int status = ::pclose(pipe);
  run.wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

std::string shell_quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace eyestream::pipeline
