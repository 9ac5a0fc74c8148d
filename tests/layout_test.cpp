// The source tree's floors: io, retina and glare never include each other
// or pipeline; inside pipeline, geometry < settings < eye < api < report <
// preview < run < bench < tools < library, and a folder includes only its
// own floor and those below it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <string>
#include <vector>

namespace eyestream {
namespace {

namespace fs = std::filesystem;

// The project's includes of a file: "folder/.../name.hpp".
std::vector<std::string> includes(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> found;
  // "folder/name.hpp", and the library's own <eyestream/...> (pipeline/api).
  const std::regex line(R"(^\s*#\s*include\s*["<]([a-z_]+/[a-z_/0-9]+\.hpp)[">])");
  std::smatch m;
  for (std::string s; std::getline(in, s);)
    if (std::regex_search(s, m, line))
      found.push_back(m[1].str().rfind("eyestream/", 0) == 0 ? "pipeline/api/" + m[1].str() : m[1].str());
  return found;
}

// The floor of a path relative to the source root ("pipeline/eye/x.hpp" -> "pipeline/eye").
std::string floor_of(const std::string& relative) {
  const size_t a = relative.find('/');
  if (a == std::string::npos) return "";
  const std::string top = relative.substr(0, a);
  if (top != "pipeline") return top;
  const size_t b = relative.find('/', a + 1);
  return b == std::string::npos ? "pipeline" : relative.substr(0, b);
}

TEST(Layout, EveryFolderIncludesOnlyItsOwnFloorAndThoseBelow) {
  const fs::path root = EYESTREAM_SOURCE_DIR;
  // Rank by floor; the model's three libraries share rank 0 and may not
  // include one another.
  const std::map<std::string, int> rank = {
      {"io", 0},           {"retina", 0},         {"glare", 0},       {"samples", 1},
      {"pipeline/geometry", 2}, {"pipeline/memory", 2}, {"pipeline/settings", 3}, {"pipeline/eye", 4}, {"pipeline/api", 5},
      {"pipeline/report", 6},  {"pipeline/preview", 7},  {"pipeline/run", 8},  {"pipeline/bench", 9},
      {"pipeline/tools", 10},  {"pipeline/library", 11}, {"pipeline", 12}};
  int checked = 0;
  for (const std::string top : {"io", "retina", "glare", "samples", "pipeline"})
    for (const auto& e : fs::recursive_directory_iterator(root / top)) {
      const std::string ext = e.path().extension().string();
      if (ext != ".cpp" && ext != ".hpp") continue;
      const std::string self = fs::relative(e.path(), root).generic_string();
      const std::string from = floor_of(self);
      ASSERT_TRUE(rank.count(from)) << self << ": a folder the layout does not name";
      for (const std::string& inc : includes(e.path())) {
        const std::string to = floor_of(inc);
        if (!rank.count(to) || to == from) continue;  // system-like paths, or the same floor
        ++checked;
        EXPECT_LT(rank.at(to), rank.at(from)) << self << " includes " << inc;
        if (rank.at(from) == 0) ADD_FAILURE() << self << " includes " << inc << ": io, retina and glare stand alone";
      }
    }
  EXPECT_GT(checked, 100) << "the includes were not found";
}

// A newcomer can take in each of pipeline's folders: none holds more than
// about 15 source files (17 at most).
TEST(Layout, NoPipelineFolderHoldsMoreThanAboutFifteenFiles) {
  for (const auto& folder : fs::directory_iterator(fs::path(EYESTREAM_SOURCE_DIR) / "pipeline")) {
    if (!folder.is_directory()) continue;
    int files = 0;
    for (const auto& e : fs::directory_iterator(folder.path()))
      files += e.path().extension() == ".cpp" || e.path().extension() == ".hpp";
    EXPECT_LE(files, 17) << folder.path().filename() << " holds " << files << " source files";
  }
}

}  // namespace
}  // namespace eyestream
