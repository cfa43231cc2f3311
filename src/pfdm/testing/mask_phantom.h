// The independent LV phantom (phantom/lv_phantom.h) voxelized into a
// short-axis label map at clinical resolution, ACDC's labels: the masks
// the segmentation tests read, with the voxel-counted volumes.
#ifndef PFDM_TESTING_MASK_PHANTOM_H_
#define PFDM_TESTING_MASK_PHANTOM_H_

#include <vector>

#include "Eigen/Geometry"
#include "pfdm/phantom/lv_phantom.h"
#include "pfdm/segmentation/label_volume.h"

namespace pfdm {

struct MaskPhantomOptions {
  int num_frames = 3;        // Systole, end-diastole to end-systole.
  double in_plane_mm = 1.5;  // Voxel size in the slices.
  double slice_mm = 8.0;     // Slice spacing (and thickness).
  int size = 90;             // nx = ny.
  bool breathing = true;
  // The slice shifted in-plane along the image's i by shift_voxels (a
  // breath-hold shift), -1 for none.
  int shifted_slice = -1;
  int shift_voxels = 0;
  LabelMap labels;  // ACDC's.
};

struct MaskPhantom {
  LvPhantom phantom;  // Its truth per frame.
  LabelVolume volume;
  // The world pose of frame 0's body: the image's axes are its x, y, z.
  Eigen::Isometry3d world_from_body0;
  // Per frame, voxel counts times the voxel's volume (ml), and the mass at
  // 1.05 g/ml.
  std::vector<double> cavity_ml, myocardium_ml;
};

// The image planes are fixed where frame 0 puts the body's short axis,
// from below the epicardial apex to past the base; a voxel is the cavity
// (lv) inside the endocardium's cut, myocardium inside the epicardium's,
// RV outside it within 12 mm and at body longitude -180 to -60 degrees
// (between the phantom's RV insertions, lv_phantom.h); a slice whose cut
// misses some meridian (past the base) holds none of that surface.
MaskPhantom MakeMaskPhantom(const MaskPhantomOptions& options);

}  // namespace pfdm

#endif  // PFDM_TESTING_MASK_PHANTOM_H_
