#include "pfdm/io/rv_insertion_source.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <vector>

#include "pfdm/io/landmark_axis.h"
#include "pfdm/io/point_reader.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

// Coordinates beyond this are not a heart's in mm (input_file.h bounds
// coordinates likewise).
constexpr double kLargestCoordinate = 1e5;

std::vector<double> Numbers(const std::string& text) {
  std::vector<double> numbers;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    char* end = nullptr;
    const double value = std::strtod(item.c_str(), &end);
    if (item.empty() || end == item.c_str() || *end != '\0' ||
        !std::isfinite(value) || std::abs(value) > kLargestCoordinate) {
      return {};
    }
    numbers.push_back(value);
  }
  if (!text.empty() && text.back() == ',') return {};
  return numbers;
}

}  // namespace

std::optional<RvInsertion> ParseRvInsertion(const std::string& text) {
  if (text.empty()) return std::nullopt;
  const std::vector<double> n = Numbers(text);
  if (n.size() != 3 && n.size() != 6) {
    throw InputError("--rv_insertion '" + text +
                     "': must be x,y,z (the anterior RV insertion) or "
                     "x,y,z,x,y,z (anterior, then inferior), mm");
  }
  RvInsertion insertion;
  insertion.source = "--rv_insertion";
  insertion.anterior.emplace_back(n[0], n[1], n[2]);
  if (n.size() == 6) {
    insertion.inferior.emplace_back(n[3], n[4], n[5]);
    if ((insertion.inferior[0] - insertion.anterior[0]).norm() < 1.0) {
      throw InputError(
          "--rv_insertion: the anterior and inferior insertions must be at "
          "least 1 mm apart");
    }
  }
  return insertion;
}

std::optional<RvInsertion> RvInsertionFrom(const std::string& flag_text,
                                           const std::string& points) {
  if (auto given = ParseRvInsertion(flag_text)) return given;
  const std::string file = FrameZeroGuidePoints(points);
  if (file.empty()) return std::nullopt;
  PointSequence landmarks;
  try {
    landmarks = ReadGpFiles(file, {"RV_INSERT"});
  } catch (const InputError&) {
    return std::nullopt;  // None; a bad file fails when the points are read.
  }
  RvInsertion insertion;
  for (const DataPoint& p : landmarks.frames[0].points) {
    insertion.unlabelled.push_back(p.position);
  }
  if (insertion.unlabelled.empty()) return std::nullopt;
  insertion.source = std::to_string(insertion.unlabelled.size()) +
                     " RV_INSERT points of " +
                     std::filesystem::path(file).filename().string();
  return insertion;
}

}  // namespace pfdm
