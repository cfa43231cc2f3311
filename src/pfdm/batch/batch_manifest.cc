#include "pfdm/batch/batch_manifest.h"

#include <filesystem>
#include <set>
#include <sstream>

// libfccp copies file names with strncpy into fixed buffers, on purpose
// (CMakeLists.txt says the same for point_reader.cc).
#pragma GCC diagnostic ignored "-Wstringop-truncation"
#include "libfccp/csv.h"
#include "pfdm/util/error.h"
#include "pfdm/util/input_file.h"

namespace pfdm {
namespace {

bool PlainName(const std::string& name) {
  if (name.empty() || name[0] == '.') return false;
  // The batch's own files beside the case folders, and their temporaries.
  if (name.rfind("summary.csv", 0) == 0 ||
      name.find(".tmp.") != std::string::npos) {
    return false;
  }
  for (char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                    (c >= '0' && c <= '9') || c == '.' || c == '_' || c == '-';
    if (!ok) return false;
  }
  return true;
}

}  // namespace

std::vector<BatchCase> ReadManifest(const std::string& path) {
  std::vector<BatchCase> cases;
  std::set<std::string> names;
  const std::filesystem::path folder =
      std::filesystem::path(path).parent_path();
  const std::string text = ReadInputFile(path);
  try {
    io::CSVReader<3, io::trim_chars<' ', '\t'>,
                  io::double_quote_escape<',', '"'>, io::throw_on_overflow,
                  io::empty_line_comment>
        in(path, text.data(), text.data() + text.size());
    in.read_header(io::ignore_extra_column | io::ignore_missing_column, "case",
                   "points", "contours");
    for (const char* column : {"case", "points"}) {
      if (!in.has_column(column)) {
        throw InputError(path + ": missing column '" + column + "'");
      }
    }
    std::string name, points, contours;
    while (in.read_row(name, points, contours)) {
      const std::string where = path + ":" + std::to_string(in.get_file_line());
      if (!PlainName(name)) {
        throw InputError(where + ": case '" + Clip(name) +
                         "' is not a plain folder name (letters, digits, "
                         "'.', '_', '-'; not summary.csv or *.tmp.*)");
      }
      if (!names.insert(name).second) {
        throw InputError(where + ": case '" + Clip(name) + "' appears twice");
      }
      if (points.empty())
        throw InputError(where + ": case '" + Clip(name) + "' has no points");
      std::filesystem::path points_path(points);
      if (points_path.is_relative()) points_path = folder / points_path;
      cases.push_back({name, points_path.lexically_normal().string(), contours,
                       static_cast<int>(in.get_file_line())});
    }
  } catch (const io::error::base& error) {
    // libfccp's own messages run over several clauses; say it in one.
    std::string message = "not a valid CSV row";
    if (dynamic_cast<const io::error::can_not_open_file*>(&error)) {
      message = "cannot open the file";
    } else if (dynamic_cast<const io::error::header_missing*>(&error)) {
      message = "empty file, no header";
    } else if (dynamic_cast<const io::error::too_few_columns*>(&error)) {
      message = "too few columns";
    } else if (dynamic_cast<const io::error::too_many_columns*>(&error)) {
      message = "too many columns";
    } else if (dynamic_cast<const io::error::duplicated_column_in_header*>(
                   &error)) {
      message = "a column appears twice in the header";
    }
    const auto* line = dynamic_cast<const io::error::with_file_line*>(&error);
    throw InputError(path +
                     (line && line->file_line > 0
                          ? ":" + std::to_string(line->file_line)
                          : "") +
                     ": " + message);
  }
  if (cases.empty()) throw InputError(path + ": no cases");
  return cases;
}

Shard ParseShard(const std::string& text) {
  // Digits only: a stream also read ' 0/1' and '+0/1' (issue 29).
  const auto digits = [&](size_t begin, size_t end) {
    return end > begin && end - begin <= 9 &&
           text.find_first_not_of("0123456789", begin) >= end;
  };
  const size_t slash = text.find('/');
  Shard shard{-1, 0};
  if (slash != std::string::npos && digits(0, slash) &&
      digits(slash + 1, text.size())) {
    shard.index = std::stoi(text.substr(0, slash));
    shard.count = std::stoi(text.substr(slash + 1));
  }
  if (shard.count < 1 || shard.index < 0 || shard.index >= shard.count) {
    throw InputError("--shard must be i/n with 0 <= i < n, got '" + Clip(text) +
                     "'");
  }
  return shard;
}

std::vector<BatchCase> CasesOfShard(const std::vector<BatchCase>& cases,
                                    const Shard& shard) {
  std::vector<BatchCase> mine;
  for (size_t r = 0; r < cases.size(); ++r) {
    if (static_cast<int>(r % shard.count) == shard.index)
      mine.push_back(cases[r]);
  }
  return mine;
}

}  // namespace pfdm
