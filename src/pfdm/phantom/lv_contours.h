// Contour points of the analytic LV phantom (sax-slices sampling): where
// fixed short-axis planes, and long-axis planes through frame 0's axis,
// cut the moving wall (lv_slices.h), drawn with an error in the image
// plane only.
#ifndef PFDM_PHANTOM_LV_CONTOURS_H_
#define PFDM_PHANTOM_LV_CONTOURS_H_

#include <cstdint>
#include <random>
#include <vector>

#include "Eigen/Geometry"
#include "pfdm/phantom/lv_phantom.h"
#include "pfdm/phantom/lv_slices.h"
#include "pfdm/util/point_data.h"

namespace pfdm {

// Frame `motion`'s contour points where the short-axis `planes` cut the
// wall, `per_contour` a plane and surface at uniformly random ED
// longitudes; ids from first_id on.
std::vector<DataPoint> SliceContours(const LvShape& shape,
                                     const LvPhantomOptions& options,
                                     const LvFrameMotion& motion,
                                     const std::vector<LvImagePlane>& planes,
                                     int per_contour, std::int64_t first_id,
                                     std::mt19937* placement,
                                     std::mt19937* noise_random);

// Frame `motion`'s contour points where options.num_long_axis_planes
// long-axis planes (180 / n degrees apart) cut the wall, `per_contour` a
// plane and surface at uniformly random ED heights, alternately on the
// plane's two sides; ids from first_id on.
std::vector<DataPoint> LongAxisContours(
    const LvShape& shape, const LvPhantomOptions& options,
    const LvFrameMotion& motion, const Eigen::Isometry3d& ed_world_from_body,
    int per_contour, std::int64_t first_id, std::mt19937* placement,
    std::mt19937* noise_random);

}  // namespace pfdm

#endif  // PFDM_PHANTOM_LV_CONTOURS_H_
