// Finding the files of a numbered frame sequence.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace eyestream::io {

struct SequenceEntry {
  std::string path;
  std::int64_t number;  // frame number in the pattern; position for folders
};

// The time of entry i of a sequence: (number_i - number_0) / fps, so a
// skipped frame keeps the timing of the rest.
double sequence_time(const std::vector<SequenceEntry>& entries, size_t i, double frames_per_second);

// True when `pattern` holds one printf integer conversion (%d, %05d, %5d).
bool is_printf_pattern(const std::string& pattern);

// The path's extension in lower case, with its dot (".exr"); "" if none.
std::string lower_extension(const std::string& path);

// Expands a printf pattern to a file name for `number`.
std::string format_pattern(const std::string& pattern, std::int64_t number);

// Lists the frames of `input`: a printf pattern (the numbers found on disk,
// from the smallest to the largest), a folder (its files ending in one of
// `extensions`: numbered by the digits their names end in, a gap refused
// as a pattern's unless skip_missing; by their position by name when a name
// has no number or two share one), or a single file. A gap in a numbered sequence is
// an InputError naming the first missing file, unless skip_missing.
// No frame at all is an InputError naming `input`.
// `gap_hint` ends the message of a gap ("use --skip-missing ..." for run).
std::vector<SequenceEntry> list_sequence(const std::string& input, const std::vector<std::string>& extensions,
                                         bool skip_missing,
                                         const std::string& gap_hint = "use --skip-missing to go on without it");

}  // namespace eyestream::io
