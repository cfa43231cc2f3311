#include "pfdm/io/point_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "libfccp/csv.h"
#include "pfdm/io/frame_times.h"
#include "pfdm/io/gp_file_header.h"
#include "pfdm/io/point_spread.h"
#include "pfdm/util/error.h"
#include "pfdm/util/input_file.h"

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
  if (const auto* named =
          dynamic_cast<const io::error::with_column_name*>(&error)) {
    column = named->column_name;
  }
  std::string what;
  if (dynamic_cast<const io::error::can_not_open_file*>(&error)) {
    what = "cannot open the file";
  } else if (dynamic_cast<const io::error::missing_column_in_header*>(&error)) {
    what = "missing column '" + column + "'";
  } else if (dynamic_cast<const io::error::duplicated_column_in_header*>(
                 &error)) {
    what = "column '" + column + "' appears twice";
  } else if (dynamic_cast<const io::error::header_missing*>(&error)) {
    what = "empty file, no header";
  } else if (dynamic_cast<const io::error::too_few_columns*>(&error)) {
    what = "too few columns";
  } else if (dynamic_cast<const io::error::too_many_columns*>(&error)) {
    what = "too many columns";
  } else if (dynamic_cast<const io::error::escaped_string_not_closed*>(
                 &error)) {
    what = "a quoted field is not closed";
  } else if (dynamic_cast<const io::error::line_length_limit_exceeded*>(
                 &error)) {
    what = "line too long";
  } else if (dynamic_cast<const io::error::integer_overflow*>(&error) ||
             dynamic_cast<const io::error::integer_underflow*>(&error)) {
    what = "column '" + column + "' is out of range";
  } else if (!column.empty()) {
    const auto* content =
        dynamic_cast<const io::error::with_column_content*>(&error);
    what = "column '" + column + "' is not a number" +
           (content ? ": '" + Clip(content->column_content) + "'" : "");
  } else {
    // libfccp's raw message escapes and repeats the file name; keep the gist.
    what = "not a valid CSV row";
  }
  return InputError(where + ": " + what);
}

// "PATH:LINE: column 'NAME'", built only for a message (built for every
// value, it was a third of reading).
std::string Where(const std::string& path, unsigned line, const char* name) {
  return path + ":" + std::to_string(line) + ": column '" + name + "'";
}

// libfccp splits the fields; its own float parser rounds differently from
// strtod, so numbers are converted by the standard library, which makes
// written files read back bit for bit.  Throws "PATH:LINE: column 'NAME'
// is not a (finite) number".
double ParseFinite(const std::string& path, unsigned line, const char* name,
                   const char* text) {
  double value = 0.0;
  const char* end = text + std::strlen(text);
  // from_chars refuses the explicit plus sign that strtod and writers allow.
  const char* begin = text[0] == '+' && text[1] != '-' ? text + 1 : text;
  const auto [rest, error] = std::from_chars(begin, end, value);
  if (error == std::errc::result_out_of_range) {
    throw InputError(Where(path, line, name) + " is out of range: '" +
                     Clip(text) + "'");
  }
  if (error != std::errc() || rest != end || rest == begin) {
    throw InputError(Where(path, line, name) + " is not a number: '" +
                     Clip(text) + "'");
  }
  if (!std::isfinite(value)) {
    throw InputError(Where(path, line, name) + " is not a finite number");
  }
  return value;
}

double ParseCoordinate(const std::string& path, unsigned line, const char* name,
                       const char* text) {
  const double value = ParseFinite(path, line, name, text);
  // Squares of 1e155 overflow inside the solver (a Ceres CHECK aborted the
  // program, issue 14); no heart lies a kilometre from the scanner origin.
  if (std::abs(value) > kMaxCoordinateMm) {
    throw InputError(Where(path, line, name) + " is out of range: '" +
                     Clip(text) + "' (more than 1e6 mm from the origin)");
  }
  return value;
}

// Each id once in a frame, checked by sorting once the file is read (a set
// per frame took a tree node per point): a repeat is named at its own line,
// the file's first such line when there are several.
void CheckIdsOncePerFrame(
    const std::string& path,
    const std::map<long long, std::vector<DataPoint>>& frames,
    const std::map<long long, std::vector<unsigned>>& lines) {
  unsigned first_line = std::numeric_limits<unsigned>::max();
  std::string what;
  for (const auto& entry : frames) {
    // Not a structured binding: C++17 lambdas cannot capture one (clang,
    // which the fuzz build uses, refuses it).
    const long long frame = entry.first;
    const std::vector<DataPoint>& points = entry.second;
    const std::vector<unsigned>& at = lines.at(frame);
    std::vector<size_t> order(points.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
      return std::make_pair(points[a].id, at[a]) <
             std::make_pair(points[b].id, at[b]);
    });
    for (size_t j = 1; j < order.size(); ++j) {
      const size_t i = order[j];
      if (points[i].id == points[order[j - 1]].id && at[i] < first_line) {
        first_line = at[i];
        what = "id " + std::to_string(points[i].id) +
               " appears twice in frame " + std::to_string(frame);
      }
    }
  }
  if (!what.empty()) {
    throw InputError(path + ":" + std::to_string(first_line) + ": " + what);
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

// The optional surface column: which wall a point lies on (mesh-points
// writes it for a mesh of one wall).
WallLayer ParseSurface(const std::string& path, unsigned line,
                       const char* text) {
  const std::string word = text;
  if (word == "endo") return WallLayer::kEndocardium;
  if (word == "epi") return WallLayer::kEpicardium;
  if (word.empty() || word == "midwall") return WallLayer::kAnywhere;
  throw InputError(Where(path, line, "surface") + " is '" + Clip(text) +
                   "' (expected endo, midwall, epi or empty)");
}

}  // namespace

PointSequence ReadPointsCsv(const std::string& path) {
  // Read whole first: a folder, FIFO or NUL byte is refused up front.
  const std::string text = ReadInputFile(path);
  std::map<long long, std::vector<DataPoint>> frames;
  std::map<long long, std::vector<unsigned>> lines;  // Each point's.
  FrameTimes times;
  try {
    // Blank lines (a trailing one, say) are skipped, not short rows.
    io::CSVReader<7, io::trim_chars<' ', '\t'>,
                  io::double_quote_escape<',', '"'>, io::throw_on_overflow,
                  io::empty_line_comment>
        in(path, text.data(), text.data() + text.size());
    in.read_header(io::ignore_extra_column | io::ignore_missing_column, "frame",
                   "id", "x", "y", "z", "time_ms", "surface");
    for (const char* name : {"frame", "id", "x", "y", "z"}) {
      if (!in.has_column(name)) {
        throw InputError(path + ": missing column '" + name + "'");
      }
    }
    long long frame, id;
    char *x = nullptr, *y = nullptr, *z = nullptr;
    char *time = nullptr, *surface = nullptr;  // Optional columns.
    // The rows of a frame mostly come together: its lists, looked up once.
    long long listed = -1;
    std::vector<DataPoint>* points = nullptr;
    std::vector<unsigned>* point_lines = nullptr;
    while (in.read_row(frame, id, x, y, z, time, surface)) {
      const unsigned line = in.get_file_line();
      const Eigen::Vector3d position(ParseCoordinate(path, line, "x", x),
                                     ParseCoordinate(path, line, "y", y),
                                     ParseCoordinate(path, line, "z", z));
      if (frame < 0) {
        throw InputError(path + ":" + std::to_string(line) +
                         ": negative frame " + std::to_string(frame));
      }
      if (points == nullptr || frame != listed) {
        listed = frame;
        points = &frames[frame];
        point_lines = &lines[frame];
      }
      if (time != nullptr) {
        times.Add(path, line, frame, ParseFinite(path, line, "time_ms", time));
      }
      points->push_back(
          {id, position,
           surface ? ParseSurface(path, line, surface) : WallLayer::kAnywhere});
      point_lines->push_back(line);
    }
  } catch (const io::error::base& error) {
    throw Restate(path, error);
  }
  CheckIdsOncePerFrame(path, frames, lines);
  PointSequence sequence = Assemble(path, std::move(frames));
  sequence.time_ms = times.Times(path);
  for (const Frame& frame : sequence.frames) {
    CheckPointsLieTogether(path, frame.index, frame.points,
                           lines.at(frame.index));
  }
  return sequence;
}

namespace {

// biv-me's LV contours name their wall: SAX_LV_ENDOCARDIAL,
// LAX_LV_EPICARDIAL and so on.  The aortic valve points end the cavity's
// outflow tract (lv-cavity), so they are the endocardium's too.
WallLayer ContourLayer(const std::string& type) {
  if (type == "AORTA_VALVE") return WallLayer::kEndocardium;
  auto ends_with = [&](const std::string& tail) {
    return type.size() >= tail.size() &&
           type.compare(type.size() - tail.size(), tail.size(), tail) == 0;
  };
  if (ends_with("_LV_ENDOCARDIAL")) return WallLayer::kEndocardium;
  if (ends_with("_LV_EPICARDIAL")) return WallLayer::kEpicardium;
  return WallLayer::kAnywhere;
}

// The time frames a GPFile's `time frame` column names.  biv-me labels the
// rows of one long-axis slice 1.0 in every frame's file (all 25 of patient
// 1's), so a 1 on the rows of a single slice (frameID) is that label, not a
// frame; a 1 on two slices, or any other second value, is a second frame.
class TimeFrames {
 public:
  // slice: the row's frameID, nullptr when the file has none (then every
  // value is a frame).
  void Add(long long frame, const char* slice) {
    Seen& seen = seen_[frame];
    if (slice == nullptr || (seen.rows > 0 && seen.slice != slice)) {
      seen.several = true;
    }
    if (seen.rows++ == 0 && slice != nullptr) seen.slice = slice;
  }

  // Throws "FILE: holds N time frames (A, B, C in column 'time frame') ..."
  // for more than one: fitted as one frame, 3 frames' contours once made
  // one frame of 1,500 points (issue 29).  Not split by the column: the
  // label above would put a slice of each frame into frame 1.
  void CheckOne(const std::string& file) const {
    std::vector<long long> frames;
    for (const auto& [frame, seen] : seen_) {
      if (frame != 1 || seen.several || seen_.size() == 1) {
        frames.push_back(frame);
      }
    }
    if (frames.size() <= 1) return;
    std::string list;
    for (size_t i = 0; i < frames.size(); ++i) {
      if (i == 4 && frames.size() > 5) {
        list += ", ...";
        i = frames.size() - 1;
      }
      list += (i > 0 ? ", " : "") + std::to_string(frames[i]);
    }
    throw InputError(file + ": holds " + std::to_string(frames.size()) +
                     " time frames (" + list +
                     " in column 'time frame'); a GPFile is one frame: give "
                     "a folder of GPFile_*.txt, one per frame");
  }

 private:
  struct Seen {
    std::string slice;
    long long rows = 0;
    bool several = false;
  };
  std::map<long long, Seen> seen_;
};

// A row's `time frame`: a whole number from 0 (biv-me writes 1.0 too).
long long ParseTimeFrame(const std::string& file, unsigned line,
                         const char* text) {
  const double value = ParseFinite(file, line, "time frame", text);
  if (!(value >= 0.0 && value <= 1e6 && value == std::floor(value))) {
    throw InputError(Where(file, line, "time frame") +
                     " is not a frame number (a whole number from 0): '" +
                     Clip(text) + "'");
  }
  return static_cast<long long>(value);
}

void CheckWeight(const std::string& file, unsigned line, const char* text) {
  if (ParseFinite(file, line, "weight", text) < 0.0) {
    throw InputError(Where(file, line, "weight") + " is negative: '" +
                     Clip(text) + "'");
  }
}

struct GpFilePoints {
  std::vector<DataPoint> points;  // The kept rows'.
  std::vector<unsigned> lines;
};

// One file's rows of the kept contour types, numbered from *next_id on;
// every row's numbers are checked, kept or not.
GpFilePoints ReadGpFile(const std::string& file,
                        const std::set<std::string>& keep,
                        std::int64_t* next_id) {
  bool headerless = false;
  const std::string text =
      WithGpFileHeader(file, ReadInputFile(file), &headerless);
  GpFilePoints kept;
  TimeFrames time_frames;
  try {
    io::CSVReader<7, io::trim_chars<' '>, io::no_quote_escape<'\t'>,
                  io::throw_on_overflow, io::empty_line_comment>
        in(file, text.data(), text.data() + text.size());
    // frameID, weight and time frame are checked when there.
    in.read_header(io::ignore_extra_column | io::ignore_missing_column, "x",
                   "y", "z", "contour type", "frameID", "weight", "time frame");
    // The header put before a file without one is no line of the file.
    if (headerless) in.set_file_line(0);
    for (const char* name : {"x", "y", "z", "contour type"}) {
      if (!in.has_column(name)) {
        throw InputError(file + ": missing column '" + name + "'");
      }
    }
    char *x = nullptr, *y = nullptr, *z = nullptr, *type = nullptr;
    char *slice = nullptr, *weight = nullptr, *time = nullptr;
    while (in.read_row(x, y, z, type, slice, weight, time)) {
      const unsigned line = in.get_file_line();
      const Eigen::Vector3d position(ParseCoordinate(file, line, "x", x),
                                     ParseCoordinate(file, line, "y", y),
                                     ParseCoordinate(file, line, "z", z));
      if (weight != nullptr) CheckWeight(file, line, weight);
      if (time != nullptr) {
        time_frames.Add(ParseTimeFrame(file, line, time), slice);
      }
      if (!keep.empty() && keep.count(type) == 0) continue;
      kept.points.push_back({(*next_id)++, position, ContourLayer(type)});
      kept.lines.push_back(line);
    }
  } catch (const io::error::base& error) {
    throw Restate(file, error);
  }
  time_frames.CheckOne(file);
  return kept;
}

// A folder's GPFile_*.txt in name order, or the one file.
std::vector<std::string> GpFilesAt(const std::string& path) {
  if (!std::filesystem::is_directory(path)) return {path};
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(path)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("GPFile_", 0) == 0 && entry.path().extension() == ".txt") {
      files.push_back(entry.path().string());
    }
  }
  std::sort(files.begin(), files.end());
  if (files.empty()) {
    throw InputError(path + ": no GPFile_*.txt in this folder");
  }
  return files;
}

}  // namespace

PointSequence ReadGpFiles(const std::string& path,
                          const std::vector<std::string>& contour_types,
                          EmptyFrames empty_frames) {
  const std::vector<std::string> files = GpFilesAt(path);
  const std::set<std::string> keep(contour_types.begin(), contour_types.end());
  std::map<long long, std::vector<DataPoint>> frames;
  std::int64_t next_id = 0;
  for (size_t index = 0; index < files.size(); ++index) {
    GpFilePoints kept = ReadGpFile(files[index], keep, &next_id);
    CheckPointsLieTogether(files[index], static_cast<int>(index), kept.points,
                           kept.lines);
    frames[index] = std::move(kept.points);
  }
  // A filter that matches nothing anywhere is a wrong type name, not a
  // frame without contours: say so once, for the whole input.
  std::string what = "no points";
  if (!contour_types.empty()) {
    what += " of contour types ";
    for (size_t i = 0; i < contour_types.size(); ++i) {
      what += (i > 0 ? "," : "") + contour_types[i];
    }
  }
  if (empty_frames == EmptyFrames::kRefuse) {
    if (next_id == 0) throw InputError(path + ": " + what);
    for (const auto& [index, points] : frames) {
      if (points.empty()) {
        throw InputError(files[index] + ": frame " + std::to_string(index) +
                         ": " + what);
      }
    }
  }
  PointSequence sequence = Assemble(path, std::move(frames));
  sequence.contour_types = contour_types;
  return sequence;
}

std::vector<std::string> ExpandContourAlias(const std::string& spec) {
  std::vector<std::string> types;
  std::istringstream in(spec);
  std::string item;
  while (std::getline(in, item, ',')) {
    // "lv-endo, lv-epi" as typed in a shell or a manifest cell.
    item.erase(0, item.find_first_not_of(" \t"));
    item.erase(item.find_last_not_of(" \t") + 1);
    if (item == "lv-endo" || item == "lv-cavity") {
      types.insert(types.end(), {"SAX_LV_ENDOCARDIAL", "LAX_LV_ENDOCARDIAL"});
      if (item == "lv-cavity") types.push_back("AORTA_VALVE");
    } else if (item == "lv-epi") {
      types.insert(types.end(), {"SAX_LV_EPICARDIAL", "LAX_LV_EPICARDIAL"});
    } else if (!item.empty()) {
      types.push_back(item);
    }
  }
  return types;
}

}  // namespace pfdm
