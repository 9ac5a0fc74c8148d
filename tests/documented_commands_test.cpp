// The commands the documentation shows cannot drift from the program: every
// `eyestream SUBCOMMAND --option ...` line in a code block of README.md and
// docs/*.md names a sub-command the program has and options that sub-command
// takes (checked against its own --help). Options after a bare `--` belong to
// the run commands `chunks` prints. (docs/commands.md is generated and
// checked by CommandReference.*.)
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/test_support.hpp"

namespace eyestream {
namespace {

namespace fs = std::filesystem;

struct Documented {
  std::string where;  // file:line
  std::string sub;    // "" for the program's own options
  std::vector<std::string> options;
};

std::vector<std::string> words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// The eyestream invocations in the fenced code blocks of a Markdown file.
std::vector<Documented> documented_in(const fs::path& file) {
  std::ifstream in(file);
  std::vector<Documented> found;
  bool fenced = false;
  int line_no = 0;
  std::string pending;  // a command continued with a backslash
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    const size_t indent = line.find_first_not_of(' ');
    if (indent != std::string::npos && line.compare(indent, 3, "```") == 0) {
      fenced = !fenced;
      continue;
    }
    if (!fenced) continue;
    if (!line.empty() && line.back() == '\\') {
      line.pop_back();
      pending += line + " ";
      continue;
    }
    line = pending + line;
    pending.clear();
    // A comment after the command, then one command per shell segment.
    const size_t hash = line.find(" #");
    if (hash != std::string::npos) line.resize(hash);
    for (char sep : {'|', ';', '&', '>', '<'})
      for (char& c : line)
        if (c == sep) c = '\n';
    std::istringstream segments(line);
    for (std::string segment; std::getline(segments, segment);) {
      const std::vector<std::string> w = words(segment);
      size_t at = 0;
      while (at < w.size() && w[at] == "$") ++at;
      if (at >= w.size() || !(w[at] == "eyestream" || w[at] == "build/eyestream")) continue;
      Documented d{file.filename().string() + ":" + std::to_string(line_no), "", {}};
      ++at;
      if (at < w.size() && w[at][0] != '-') d.sub = w[at++];
      bool passed_on = false;  // after a bare "--": options of the chunks' run commands
      for (; at < w.size(); ++at) {
        if (w[at] == "--") {
          passed_on = true;
          continue;
        }
        if (w[at].size() < 2 || w[at][0] != '-' || w[at] == "-" || std::isdigit(static_cast<unsigned char>(w[at][1])))
          continue;  // values, "-" (standard input or output), negative numbers
        std::string option = w[at].substr(0, w[at].find('='));
        d.options.push_back(passed_on ? "run " + option : option);
      }
      found.push_back(d);
    }
  }
  return found;
}

TEST(DocumentedCommands, EveryShownCommandAndOptionExists) {
  const fs::path root = EYESTREAM_SOURCE_DIR;
  std::vector<fs::path> files = {root / "README.md"};
  for (const auto& e : fs::directory_iterator(root / "docs"))
    if (e.path().extension() == ".md" && e.path().filename() != "commands.md") files.push_back(e.path());
  std::map<std::string, std::string> help;  // sub-command -> its --help
  const auto help_of = [&](const std::string& sub) -> const std::string& {
    if (!help.count(sub)) help[sub] = test::run_eyestream((sub.empty() ? "" : sub + " ") + "--help").output;
    return help[sub];
  };
  // The options a --help lists: the first column of its option lines
  // ("  -i,--input TEXT ...", "  --glare,--no-glare{false} ..."), split at commas.
  const auto options_of = [&](const std::string& sub) {
    std::set<std::string> names;
    std::istringstream lines(help_of(sub));
    for (std::string line; std::getline(lines, line);) {
      if (line.rfind("  -", 0) != 0) continue;
      std::string spec = words(line).front();
      std::istringstream parts(spec);
      for (std::string part; std::getline(parts, part, ',');) names.insert(part.substr(0, part.find('{')));
    }
    return names;
  };
  int commands = 0, options = 0;
  for (const fs::path& f : files)
    for (const Documented& d : documented_in(f)) {
      ++commands;
      const std::string& h = help_of(d.sub);
      EXPECT_EQ(h.find("eyestream: error:"), std::string::npos) << d.where << ": `eyestream " << d.sub << "` is not a command";
      for (std::string option : d.options) {
        std::string sub = d.sub;
        if (option.rfind("run ", 0) == 0) sub = "run", option = option.substr(4);
        ++options;
        EXPECT_EQ(options_of(sub).count(option), 1u) << d.where << ": `eyestream " << sub << "` has no option " << option;
      }
    }
  EXPECT_GT(commands, 30) << "the documentation's commands were not found";
  EXPECT_GT(options, 60);
}

}  // namespace
}  // namespace eyestream
