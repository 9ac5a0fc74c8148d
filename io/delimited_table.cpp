#include "io/delimited_table.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace eyestream::io {

namespace {

std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t\r\""), e = s.find_last_not_of(" \t\r\"");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

}  // namespace

int DelimitedTable::column(const std::string& name, bool prefix) const {
  for (int i = 0; i < int(header.size()); ++i)
    if (prefix ? header[size_t(i)].rfind(name, 0) == 0 : header[size_t(i)] == name) return i;
  return -1;
}

std::vector<std::string> split_fields(const std::string& line, char delimiter) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string field;
  while (std::getline(ss, field, delimiter)) out.push_back(trim(field));
  if (!line.empty() && line.back() == delimiter) out.emplace_back();
  return out;
}

DelimitedTable parse_delimited(const std::string& text, char delimiter) {
  DelimitedTable table;
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  bool have_header = false;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    if (!have_header) {
      table.header = split_fields(line, delimiter);
      table.header_line = line_no;
      have_header = true;
      continue;
    }
    table.rows.push_back(split_fields(line, delimiter));
    table.line_numbers.push_back(line_no);
  }
  return table;
}

bool parse_number(const std::string& field, double& out, bool decimal_comma) {
  if (field.empty()) return false;
  std::string f = field;
  if (decimal_comma)
    for (char& c : f)
      if (c == ',') c = '.';
  char* end = nullptr;
  out = std::strtod(f.c_str(), &end);
  return end == f.c_str() + f.size() && std::isfinite(out);
}

}  // namespace eyestream::io
