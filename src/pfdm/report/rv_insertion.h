// The AHA segments' anchor: the RV insertion points, where the RV's free
// wall meets the septum, anterior and inferior (Cerqueira et al. 2002: the
// anterior insertion is the border of the anterior and anteroseptal
// segments, the septal segments lie between the two).
#ifndef PFDM_REPORT_RV_INSERTION_H_
#define PFDM_REPORT_RV_INSERTION_H_

#include <optional>
#include <string>
#include <vector>

#include "Eigen/Core"
#include "pfdm/model/model.h"
#include "pfdm/report/wall_motion.h"

namespace pfdm {

// World points at frame 0 (end-diastole).  Labelled points (--rv_insertion
// anterior[,inferior]) or unlabelled ones (biv-me's RV_INSERT: one anterior
// and one inferior on each short-axis slice).
struct RvInsertion {
  std::vector<Eigen::Vector3d> anterior;
  std::vector<Eigen::Vector3d> inferior;
  std::vector<Eigen::Vector3d> unlabelled;
  std::string source;  // "--rv_insertion", "RV_INSERT points", ...
};

// The material point of the reference model's mid-wall nearest `world`:
// its v (radians, in [-pi, pi)) and its ring's height fraction (0 apex
// pole, 1 base rim) along the model's axis.
struct MaterialLongitude {
  double v = 0.0;
  double height_fraction = 0.0;
  double distance_mm = 0.0;
};
MaterialLongitude NearestLongitude(const Model& reference,
                                   const Eigen::Vector3d& world);

// `layout` anchored at the insertion on the reference (frame 0) model:
// anchor_v the anterior insertion's v, direction the sense from it to the
// inferior one the short way (the septum's side).  Unlabelled points are
// paired by height (each slice's two, taken in order along the axis) and
// in each pair the anterior is the one from which the septum runs clockwise
// seen from the base, as in a right-handed patient frame (DICOM's LPS,
// RAS); so is a lone labelled anterior insertion's direction.  Points of
// the basal and mid thirds set the anchor when there are some (the AHA
// places those levels by it), else all.  Without an insertion, or when its
// points do not make one (unpaired, or a point farther from the model's
// surface than half its length), `layout` as it was with anchor saying
// why.
RegionLayout AnatomicalLayout(const Model& reference,
                              const std::optional<RvInsertion>& insertion,
                              RegionLayout layout = RegionLayout());

}  // namespace pfdm

#endif  // PFDM_REPORT_RV_INSERTION_H_
