// Output files that appear under their final name only when complete.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace eyestream::io {

// One file written under a temporary name in the destination folder and
// renamed to the final name by commit(). If the object is destroyed without
// commit(), the temporary file is removed: no partial output is left.
// Refuses (OutputError) a destination that is one of `protected_inputs`.
class StagedFile {
 public:
  explicit StagedFile(std::filesystem::path final_path);
  // With a temporary name derived from the final one and `tag`
  // (staged_temp_path), so a caller staging many files can find each
  // temporary again from its final name without keeping this object.
  StagedFile(std::filesystem::path final_path, const std::string& tag);
  ~StagedFile();
  StagedFile(const StagedFile&) = delete;
  StagedFile& operator=(const StagedFile&) = delete;
  StagedFile(StagedFile&& other) noexcept;
  StagedFile& operator=(StagedFile&& other) = delete;

  const std::filesystem::path& temp_path() const { return temp_; }
  const std::filesystem::path& final_path() const { return final_; }
  void commit();
  // Leaves the temporary file for the caller, which renames or removes it.
  void release() { done_ = true; }

 private:
  std::filesystem::path final_;
  std::filesystem::path temp_;
  bool done_ = false;
};

// The temporary name of `final_path` staged with `tag` by this process.
std::filesystem::path staged_temp_path(const std::filesystem::path& final_path, const std::string& tag);

// Removes the temporary files that processes no longer running left in
// `dir` (a killed run before --resume); returns how many.
int remove_stale_partials(const std::filesystem::path& dir);

// Writes `bytes` to a staged file; the caller commits it.
void write_all(const StagedFile& file, const std::vector<unsigned char>& bytes);

// Registers paths that outputs must never replace (the inputs of a run).
void protect_input(const std::filesystem::path& path);
// Throws OutputError if `path` names a protected input.
void check_not_input(const std::filesystem::path& path);

}  // namespace eyestream::io
