// Delimited text tables (CSV, TSV) with a header row, for gaze logs.
#pragma once

#include <string>
#include <vector>

namespace eyestream::io {

struct DelimitedTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::vector<int> line_numbers;  // 1-based file line of each row
  int header_line = 0;            // 1-based file line of the header (0: none)

  // Index of the column whose name equals `name` (or starts with it when
  // `prefix`), or -1.
  int column(const std::string& name, bool prefix = false) const;
};

// Splits `text` into rows at newlines and fields at `delimiter`, trimming
// blanks and double quotes around fields; skips empty lines and lines
// starting with '#'. The first remaining line is the header.
DelimitedTable parse_delimited(const std::string& text, char delimiter);

// One line split into trimmed fields.
std::vector<std::string> split_fields(const std::string& line, char delimiter);

// Parses a finite number; `decimal_comma` also accepts "1,5". False if the
// field is empty or not a whole number literal.
bool parse_number(const std::string& field, double& out, bool decimal_comma = false);

}  // namespace eyestream::io
