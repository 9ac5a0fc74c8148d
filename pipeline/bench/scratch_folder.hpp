// A fresh folder under the system's temp folder for `eyestream bench`'s
// scene frames and the peers' files, removed with everything in it when it
// goes out of scope.
#pragma once

#include <filesystem>

namespace eyestream::pipeline {

class ScratchFolder {
 public:
  ScratchFolder();
  ~ScratchFolder();
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace eyestream::pipeline
