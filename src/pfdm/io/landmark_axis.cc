#include "pfdm/io/landmark_axis.h"

#include <algorithm>
#include <filesystem>
#include <vector>

#include "pfdm/io/point_reader.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

// The mean of the file's points of these contour types; nullopt if none.
std::optional<Eigen::Vector3d> Mean(const std::string& file,
                                    const std::vector<std::string>& types,
                                    int* count) {
  PointSequence points;
  try {
    points = ReadGpFiles(file, types);
  } catch (const InputError&) {
    return std::nullopt;  // None of them; a bad file fails when read.
  }
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const DataPoint& p : points.frames[0].points) sum += p.position;
  *count = static_cast<int>(points.frames[0].points.size());
  return sum / *count;
}

}  // namespace

std::string FrameZeroGuidePoints(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (!fs::is_directory(path, error)) {
    return fs::path(path).filename().string().rfind("GPFile", 0) == 0 ? path
                                                                      : "";
  }
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(path, error)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("GPFile_", 0) == 0 && entry.path().extension() == ".txt") {
      files.push_back(entry.path().string());
    }
  }
  if (files.empty()) return "";
  return *std::min_element(files.begin(), files.end());
}

std::optional<AxisHint> LandmarkAxis(const std::string& points) {
  const std::string file = FrameZeroGuidePoints(points);
  if (file.empty()) return std::nullopt;
  int apexes = 0, valves = 0, mitral = 0;
  const auto apex = Mean(file, {"APEX_POINT"}, &apexes);
  const auto base = Mean(file, {"MITRAL_VALVE", "AORTA_VALVE"}, &valves);
  if (!apex || !base || !((*base - *apex).norm() >= 1.0)) return std::nullopt;
  std::string source = "APEX_POINT and MITRAL_VALVE";
  if (!Mean(file, {"MITRAL_VALVE"}, &mitral)) {
    source = "APEX_POINT and AORTA_VALVE";
  } else if (mitral < valves) {
    source += ", AORTA_VALVE";
  }
  return AxisHint{*apex, *base, source};
}

void AddLandmarkAxis(const std::string& points, FitOptions* options) {
  if (!options->hint) options->hint = LandmarkAxis(points);
}

}  // namespace pfdm
