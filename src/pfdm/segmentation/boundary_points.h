// Sub-voxel boundary points of a region in one slice: marching squares'
// vertices.
#ifndef PFDM_SEGMENTATION_BOUNDARY_POINTS_H_
#define PFDM_SEGMENTATION_BOUNDARY_POINTS_H_

#include <cstdint>
#include <vector>

#include "Eigen/Core"

namespace pfdm {

// One slice's region: nx x ny, inside[j * nx + i] != 0 for voxel (i, j).
struct SliceMask {
  int nx = 0, ny = 0;
  std::vector<std::uint8_t> inside;
  bool At(int i, int j) const {
    return i >= 0 && j >= 0 && i < nx && j < ny && inside[j * nx + i] != 0;
  }
};

// Where the region's indicator, smoothed by a [1 2 1] / 4 kernel along i
// and j, crosses 1/2 on the segments between neighbouring voxel centres
// (the vertices marching squares puts there, linearly interpolated),
// outside the image taken as 0: fractional (i, j).  The kernel turns a
// binary staircase into a smooth curve whose enclosed area stays the voxel
// count's (within a percent for a disk of 15 voxels' radius, the test's); a
// straight edge stays where it was.
std::vector<Eigen::Vector2d> BoundaryPoints(const SliceMask& mask);

// The region's voxel count and the mean of its voxels' (i, j).
struct RegionMoments {
  int count = 0;
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
};
RegionMoments Moments(const SliceMask& mask);

// Whether some voxel of `target` is reached from the image's border through
// voxels outside `wall` (4-connected): an LV cavity its myocardium does not
// close in.
bool ReachableFromBorder(const SliceMask& wall, const SliceMask& target);

}  // namespace pfdm

#endif  // PFDM_SEGMENTATION_BOUNDARY_POINTS_H_
