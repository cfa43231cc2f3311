#include "pfdm/io/mitral_valve_planes.h"

#include <filesystem>

#include "pfdm/io/point_reader.h"
#include "pfdm/util/error.h"

namespace pfdm {

std::vector<BasePlane> MitralValvePlanes(const std::string& gp_path) {
  const std::filesystem::path path(gp_path);
  if (!std::filesystem::is_directory(path) &&
      path.filename().string().rfind("GPFile", 0) != 0) {
    return {};
  }
  PointSequence valve;
  try {
    valve = ReadGpFiles(gp_path, {"MITRAL_VALVE"});
  } catch (const InputError&) {
    return {};  // Some frame has none: keep the flat lid for all.
  }
  std::vector<BasePlane> planes;
  for (const Frame& frame : valve.frames) {
    std::vector<Eigen::Vector3d> points;
    for (const DataPoint& p : frame.points) points.push_back(p.position);
    const std::optional<BasePlane> plane = FitBasePlane(points);
    // Points that should be a valve ring but are not: say so rather than
    // silently closing at the rim (or, before, at an arbitrary plane).
    if (!plane && points.size() >= 3) {
      throw InputError(gp_path + ": frame " + std::to_string(frame.index) +
                       ": its " + std::to_string(points.size()) +
                       " MITRAL_VALVE points lie at one place or on a line, "
                       "no plane; --base_plane rim closes at the rim");
    }
    if (!plane) return {};
    planes.push_back(*plane);
  }
  return planes;
}

}  // namespace pfdm
