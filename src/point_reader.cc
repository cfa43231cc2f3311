#include "pfdm/point_reader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include "libfccp/csv.h"
#include "pfdm/error.h"

namespace pfdm {
namespace {

// libfccp's messages repeat the file name and run over several clauses;
// restate them as "PATH:LINE: what".
InputError Restate(const std::string& path, const io::error::base& error) {
  std::string where = path;
  if (const auto* line = dynamic_cast<const io::error::with_file_line*>(&error);
      line != nullptr && line->file_line > 0) {
    where += ":" + std::to_string(line->file_line);
  }
  std::string column;
  if (const auto* named = dynamic_cast<const io::error::with_column_name*>(&error)) {
    column = named->column_name;
  }
  std::string what;
  if (dynamic_cast<const io::error::can_not_open_file*>(&error)) {
    what = "cannot open the file";
  } else if (dynamic_cast<const io::error::missing_column_in_header*>(&error)) {
    what = "missing column '" + column + "'";
  } else if (dynamic_cast<const io::error::duplicated_column_in_header*>(&error)) {
    what = "column '" + column + "' appears twice";
  } else if (dynamic_cast<const io::error::header_missing*>(&error)) {
    what = "empty file, no header";
  } else if (dynamic_cast<const io::error::too_few_columns*>(&error)) {
    what = "too few columns";
  } else if (dynamic_cast<const io::error::too_many_columns*>(&error)) {
    what = "too many columns";
  } else if (!column.empty()) {
    const auto* content = dynamic_cast<const io::error::with_column_content*>(&error);
    what = "column '" + column + "' is not a number" +
           (content ? ": '" + std::string(content->column_content) + "'" : "");
  } else {
    what = error.what();
  }
  return InputError(where + ": " + what);
}

void CheckFinite(const std::string& path, unsigned line, const char* name,
                 double value) {
  if (!std::isfinite(value)) {
    throw InputError(path + ":" + std::to_string(line) + ": column '" + name +
                     "' is not a finite number");
  }
}

// Orders frames and checks that 0..F-1 are all there.
PointSequence Assemble(const std::string& path,
                       std::map<long long, std::vector<DataPoint>> frames) {
  PointSequence sequence;
  sequence.source = path;
  if (frames.empty()) throw InputError(path + ": no points");
  int expected = 0;
  for (auto& [index, points] : frames) {
    if (index != expected) {
      throw InputError(path + ": frame " + std::to_string(expected) +
                       " has no points");
    }
    sequence.frames.push_back({expected, std::move(points)});
    ++expected;
  }
  return sequence;
}

}  // namespace

PointSequence ReadPointsCsv(const std::string& path) {
  std::map<long long, std::vector<DataPoint>> frames;
  std::map<long long, std::set<long long>> ids;
  try {
    io::CSVReader<5, io::trim_chars<' ', '\t'>, io::double_quote_escape<',', '"'>>
        in(path);
    in.read_header(io::ignore_extra_column, "frame", "id", "x", "y", "z");
    long long frame, id;
    double x, y, z;
    while (in.read_row(frame, id, x, y, z)) {
      const unsigned line = in.get_file_line();
      const std::string where = path + ":" + std::to_string(line);
      CheckFinite(path, line, "x", x);
      CheckFinite(path, line, "y", y);
      CheckFinite(path, line, "z", z);
      if (frame < 0) throw InputError(where + ": negative frame " + std::to_string(frame));
      if (!ids[frame].insert(id).second) {
        throw InputError(where + ": id " + std::to_string(id) +
                         " appears twice in frame " + std::to_string(frame));
      }
      frames[frame].push_back({id, Eigen::Vector3d(x, y, z)});
    }
  } catch (const io::error::base& error) {
    throw Restate(path, error);
  }
  return Assemble(path, std::move(frames));
}

PointSequence ReadGpFiles(const std::string& path,
                          const std::vector<std::string>& contour_types) {
  std::vector<std::string> files;
  if (std::filesystem::is_directory(path)) {
    for (const auto& entry : std::filesystem::directory_iterator(path)) {
      const std::string name = entry.path().filename().string();
      if (name.rfind("GPFile_", 0) == 0 && entry.path().extension() == ".txt") {
        files.push_back(entry.path().string());
      }
    }
    std::sort(files.begin(), files.end());
    if (files.empty()) throw InputError(path + ": no GPFile_*.txt in this folder");
  } else {
    files.push_back(path);
  }
  const std::set<std::string> keep(contour_types.begin(), contour_types.end());
  std::map<long long, std::vector<DataPoint>> frames;
  std::int64_t next_id = 0;
  for (const std::string& file : files) {
    try {
      io::CSVReader<5, io::trim_chars<' '>, io::no_quote_escape<'\t'>> in(file);
      in.read_header(io::ignore_extra_column, "x", "y", "z", "contour type",
                     "time frame");
      double x, y, z;
      std::string type;
      long long frame;
      while (in.read_row(x, y, z, type, frame)) {
        const unsigned line = in.get_file_line();
        CheckFinite(file, line, "x", x);
        CheckFinite(file, line, "y", y);
        CheckFinite(file, line, "z", z);
        if (!keep.empty() && keep.count(type) == 0) continue;
        frames[frame].push_back({next_id++, Eigen::Vector3d(x, y, z)});
      }
    } catch (const io::error::base& error) {
      throw Restate(file, error);
    }
  }
  if (frames.empty()) {
    std::string list;
    for (const auto& type : contour_types) list += (list.empty() ? "" : ",") + type;
    throw InputError("no points of contour types " + list + " in " + path);
  }
  // biv-me numbers frames by acquisition; ours run 0..F-1 in that order.
  std::map<long long, std::vector<DataPoint>> renumbered;
  long long index = 0;
  for (auto& [frame, points] : frames) renumbered[index++] = std::move(points);
  return Assemble(path, std::move(renumbered));
}

std::vector<std::string> ExpandContourAlias(const std::string& spec) {
  std::vector<std::string> types;
  std::istringstream in(spec);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (item == "lv-endo") {
      types.insert(types.end(), {"SAX_LV_ENDOCARDIAL", "LAX_LV_ENDOCARDIAL"});
    } else if (item == "lv-epi") {
      types.insert(types.end(), {"SAX_LV_EPICARDIAL", "LAX_LV_EPICARDIAL"});
    } else if (!item.empty()) {
      types.push_back(item);
    }
  }
  return types;
}

}  // namespace pfdm
