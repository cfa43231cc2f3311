#include "pfdm/io/mitral_valve_planes.h"

#include <cstdio>

#include "pfdm/io/point_reader.h"
#include "pfdm/io/point_source.h"
#include "pfdm/util/error.h"

namespace pfdm {

std::vector<BasePlane> MitralValvePlanes(const std::string& gp_path,
                                         const std::string& format) {
  // By the format the points were read with: by the name alone, a GPFile
  // read with --format gpfile under another name was closed at the rim
  // (138.8 ml) where the same file as GPFile_*.txt had its plane (issue 29).
  if (PointFormatOf(gp_path, format) != PointFormat::kGpFile) return {};
  // A frame without valve points is no error (the flat lid for all), but
  // a bad row or a stray point is: catching every error once hid them.
  const PointSequence valve =
      ReadGpFiles(gp_path, {"MITRAL_VALVE"}, EmptyFrames::kAllow);
  std::vector<BasePlane> planes;
  for (const Frame& frame : valve.frames) {
    std::vector<Eigen::Vector3d> points;
    for (const DataPoint& p : frame.points) points.push_back(p.position);
    if (points.size() < 3) return {};  // No ring: the flat lid for all.
    const std::optional<BasePlane> plane = FitBasePlane(points);
    // Points that should be a valve ring but are not: say so rather than
    // silently closing at the rim (or, before, at an arbitrary plane).
    if (!plane) {
      throw InputError(gp_path + ": frame " + std::to_string(frame.index) +
                       ": its " + std::to_string(points.size()) +
                       " MITRAL_VALVE points lie at one place or on a line, "
                       "no plane; --base_plane rim closes at the rim");
    }
    planes.push_back(*plane);
  }
  return planes;
}

void CheckPlanesBelowApex(const std::string& gp_path,
                          const std::vector<BasePlane>& planes,
                          const SequenceFit& fit) {
  if (planes.size() != fit.frames.size()) return;
  const double w = fit.config.Solid() ? -1.0 : 0.0;  // The cavity's wall.
  for (size_t t = 0; t < planes.size(); ++t) {
    const Model model = fit.ModelAt(static_cast<int>(t));
    // Oriented toward the base as CavityVolumeMl orients it.
    Eigen::Vector3d normal = planes[t].normal.normalized();
    if (normal.dot(model.Rotation().col(2)) < 0.0) normal = -normal;
    const Eigen::Vector3d apex = model.WorldPoint(model.config.u_min, 0.0, w);
    const double beyond = (apex - planes[t].point).dot(normal);
    if (beyond >= 0.0) {
      char mm[32];
      std::snprintf(mm, sizeof(mm), "%.1f", beyond);
      throw InputError(gp_path + ": frame " + std::to_string(t) +
                       ": the MITRAL_VALVE plane lies " + mm +
                       " mm beyond the fitted apex, closing no cavity; "
                       "--base_plane rim closes at the rim");
    }
  }
}

}  // namespace pfdm
