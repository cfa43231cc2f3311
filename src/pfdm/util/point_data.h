// Material points over time: the data a fit consumes.
#ifndef PFDM_UTIL_POINT_DATA_H_
#define PFDM_UTIL_POINT_DATA_H_

#include <cstdint>
#include <string>
#include <vector>

#include "Eigen/Core"

namespace pfdm {

// Which surface of the wall a point lies on, when its input says so (biv-me
// contour types); tags and unlabelled points are kAnywhere.
enum class WallLayer { kAnywhere, kEndocardium, kEpicardium };

struct DataPoint {
  // The same id in several frames is the same material point (a tracked
  // tag); an id seen in one frame only is an untracked surface sample.
  std::int64_t id = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // mm
  WallLayer layer = WallLayer::kAnywhere;
};

struct Frame {
  int index = 0;
  std::vector<DataPoint> points;
};

// A contour the reader left out of the fit: a basal short-axis contour on a
// slice that holds the outflow tract beside the axis, not the ventricle
// round it (io/partial_rings.h).
struct LeftOutContour {
  int frame = 0;
  std::string contour;  // "SAX_LV_ENDOCARDIAL 2": the type and slice.
  int points = 0;
  double coverage_deg = 0.0;  // 360 less its widest gap about the axis.
};

struct PointSequence {
  std::string source;         // File or folder the points came from.
  std::vector<Frame> frames;  // frames[i].index == i.
  // Guide points: the contour types kept; empty when all were, or for
  // other inputs.
  std::vector<std::string> contour_types;
  // Per frame, its time from the trigger (ms) when the input gives one (a
  // time_ms column); empty otherwise.
  std::vector<double> time_ms;
  // Guide points: the contours left out, in frame order.
  std::vector<LeftOutContour> left_out;
  // The input closes the base itself: a segmentation's most basal LV slab
  // (its walls at the slab's basal face, or a partial ring above it), as a
  // voxel count takes it; contours end at their slice's centre.
  bool base_from_labels = false;
};

}  // namespace pfdm

#endif  // PFDM_UTIL_POINT_DATA_H_
