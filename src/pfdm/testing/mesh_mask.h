// Closed surface meshes voxelized into a short-axis label map: biv-me's
// fitted LV endocardium and biventricular epicardium (../shared/data) made
// into the mask a segmentation network would give of that heart, ACDC's
// labels, at clinical resolution.  A mask of real anatomy that neither
// pfdm's model nor its LV phantom made.
#ifndef PFDM_TESTING_MESH_MASK_H_
#define PFDM_TESTING_MESH_MASK_H_

#include <string>
#include <vector>

#include "Eigen/Core"
#include "pfdm/segmentation/label_volume.h"
#include "pfdm/util/triangle_mesh.h"

namespace pfdm {

// The stack's geometry: slices perpendicular to `to_apex` through
// `origin + (first_slice_mm + k slice_mm) to_apex`, square in-plane grids
// of `size` voxels centred on that axis.
struct StackGeometry {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d to_apex = Eigen::Vector3d::UnitZ();
  double first_slice_mm = 0.0;
  double in_plane_mm = 1.5, slice_mm = 8.0;
  int size = 0, slices = 0;
};

// world_from_voxel of that stack: i, j in the slices (i x j = to_apex), k
// from the base toward the apex.
Eigen::Matrix4d WorldFromVoxel(const StackGeometry& stack);

// Which voxel centres of slice k lie inside the closed mesh, by the parity
// of the mesh's cut crossed along each row: [j * size + i].
std::vector<bool> InsideSlice(const TriangleMesh& closed,
                              const Eigen::Matrix4d& world_from_voxel, int size,
                              int k);

struct MeshMaskFrame {
  TriangleMesh lv_endocardium;  // Open at the base; capped here.
  TriangleMesh epicardium;      // Both ventricles'; capped here.
};

struct MeshMask {
  LabelVolume volume;
  // Per frame: the LV wall thickness (mm) the myocardium is given where
  // the epicardium lies beyond it (the septum, whose RV side no mesh
  // gives): the median distance from an endocardial vertex to the nearest
  // epicardial one, over those nearer than 15 mm (the free wall).
  std::vector<double> wall_mm;
  // Per frame: voxel counts times the voxel's volume (ml), and the capped
  // endocardial mesh's own enclosed volume.
  std::vector<double> cavity_ml, myocardium_ml, mesh_cavity_ml;
};

// Frame 0's endocardium sets the stack: the axis from its rim's centroid
// to its farthest vertex, slices from half a slice above the rim to past
// the epicardium.  A voxel is the cavity (lv) inside the endocardium,
// myocardium inside the epicardium within wall_mm of the cavity (in the
// slice), and the RV the largest connected rest inside the epicardium.
MeshMask MakeMeshMask(const std::vector<MeshMaskFrame>& frames,
                      const LabelMap& labels, double in_plane_mm = 1.5,
                      double slice_mm = 8.0);

}  // namespace pfdm

#endif  // PFDM_TESTING_MESH_MASK_H_
