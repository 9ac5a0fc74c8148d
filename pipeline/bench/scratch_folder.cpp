#include "pipeline/bench/scratch_folder.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "io/error.hpp"

namespace eyestream::pipeline {

ScratchFolder::ScratchFolder() {
  // mkdtemp: a new folder of a name no one could have taken first, only
  // this user's (the peers run a script from it).
  std::string pattern = (std::filesystem::temp_directory_path() / "eyestream-bench-XXXXXX").string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  if (!::mkdtemp(name.data()))
    throw OutputError(pattern + ": cannot make a scratch folder: " + std::strerror(errno));
  path_ = name.data();
}

ScratchFolder::~ScratchFolder() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

}  // namespace eyestream::pipeline
