#include "pfdm/io/gp_file_header.h"

#include <algorithm>
#include <cstdlib>

#include "pfdm/util/error.h"

namespace pfdm {
namespace {

constexpr const char* kBivMeColumns[] = {
    "x", "y", "z", "contour type", "frameID", "weight", "time frame"};
constexpr int kRequiredColumns = 4;  // x, y, z and contour type.

bool IsBlank(const std::string& line) {
  return line.find_first_not_of(" \t\r") == std::string::npos;
}

// Whether a field (spaces around it allowed) reads whole as a number.
bool IsNumber(std::string field) {
  field.erase(0, field.find_first_not_of(' '));
  field.erase(field.find_last_not_of(" \r") + 1);
  if (field.empty()) return false;
  char* end = nullptr;
  std::strtod(field.c_str(), &end);
  return end == field.c_str() + field.size();
}

}  // namespace

std::string WithGpFileHeader(const std::string& file, const std::string& text,
                             bool* headerless) {
  *headerless = false;
  size_t begin = 0;
  int line_number = 1;
  std::string line;
  while (begin < text.size()) {
    const size_t end = std::min(text.find('\n', begin), text.size());
    line = text.substr(begin, end - begin);
    if (!IsBlank(line)) break;
    begin = end + 1;
    ++line_number;
    line.clear();
  }
  if (line.empty() || !IsNumber(line.substr(0, line.find('\t')))) return text;
  const int fields =
      1 + static_cast<int>(std::count(line.begin(), line.end(), '\t'));
  if (fields < kRequiredColumns) {
    throw InputError(file + ":" + std::to_string(line_number) +
                     ": a GPFile row without a header line needs x, y, z and "
                     "contour type (biv-me's column order), got " +
                     std::to_string(fields) + " fields");
  }
  std::string header;
  for (int i = 0; i < fields; ++i) {
    header += i == 0 ? "" : "\t";
    header += i < 7 ? kBivMeColumns[i] : "column " + std::to_string(i + 1);
  }
  *headerless = true;
  return header + "\n" + text;
}

}  // namespace pfdm
