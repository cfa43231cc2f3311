// A stack of short-axis label maps over time, as segmentation networks and
// the public datasets (ACDC, M&Ms) deliver them, and which label is which.
#ifndef PFDM_SEGMENTATION_LABEL_VOLUME_H_
#define PFDM_SEGMENTATION_LABEL_VOLUME_H_

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "Eigen/Core"
#include "Eigen/LU"  // determinant()

namespace pfdm {

// Label values of the structures pfdm reads; 0 is background.  rv may be
// absent (-1): then no RV insertion.
struct LabelMap {
  int lv = 3;   // LV blood pool (cavity).
  int myo = 2;  // LV myocardium.
  int rv = 1;   // RV blood pool.
};

// nx x ny voxels in each of nz slices, nt frames; labels[Index(i, j, k,
// t)].  world_from_voxel maps (i, j, k, 1) to world mm (the file's sform,
// else qform: scanner RAS for NIfTI).
struct LabelVolume {
  std::string source;  // File or folder.
  int nx = 0, ny = 0, nz = 0, nt = 0;
  std::vector<std::int32_t> labels;
  Eigen::Matrix4d world_from_voxel = Eigen::Matrix4d::Identity();
  // Where world_from_voxel came from: "sform", "qform" or "pixdim".
  std::string geometry;

  size_t Index(int i, int j, int k, int t) const {
    return ((static_cast<size_t>(t) * nz + k) * ny + j) * nx + i;
  }
  std::int32_t At(int i, int j, int k, int t) const {
    return labels[Index(i, j, k, t)];
  }
  // World position of the (fractional) voxel coordinate (i, j, k).
  Eigen::Vector3d World(double i, double j, double k) const {
    return (world_from_voxel * Eigen::Vector4d(i, j, k, 1.0)).head<3>();
  }
  // Spacing along i, j and k (mm): the columns' lengths.
  double Spacing(int axis) const {
    return world_from_voxel.col(axis).head<3>().norm();
  }
  double VoxelVolumeMl() const {
    return std::abs(world_from_voxel.topLeftCorner<3, 3>().determinant()) /
           1000.0;
  }
};

}  // namespace pfdm

#endif  // PFDM_SEGMENTATION_LABEL_VOLUME_H_
