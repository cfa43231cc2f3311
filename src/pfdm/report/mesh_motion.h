// Contraction measured directly on meshes whose vertices correspond over
// frames, for comparison with what a model fit reads off its functions.
#ifndef PFDM_REPORT_MESH_MOTION_H_
#define PFDM_REPORT_MESH_MOTION_H_

#include <vector>

#include "pfdm/util/triangle_mesh.h"

namespace pfdm {

struct MeshFrameMotion {
  double volume_ml = 0.0;  // Every open boundary closed by a fan.
  // Apex vertex to the centroid of the boundary (rim) vertices.
  double length_mm = 0.0;
  double longitudinal_shortening_percent = 0.0;  // 1 - L / L0.
  // Mean over vertices of 1 - rho / rho0, rho the distance from the frame's
  // own apex-to-rim-centre line; vertices with rho0 under a fifth of the
  // largest are left out (near the apex the ratio says little).
  double radial_contraction_percent = 0.0;
  // Global circumferential and longitudinal Green-Lagrange strain, percent:
  // per triangle, the deformation of its plane from frame 0 (PlaneStrain of
  // two edges), in a basis of frame 0: e_c along the turn about frame 0's
  // apex-to-rim-centre axis (right-handed, apex to base), e_l in the plane
  // toward the base; the mean over triangles weighted by frame-0 area.
  double gcs_percent = 0.0;
  double gls_percent = 0.0;
};

// frames share frames[0]'s triangles; the apex is the vertex farthest from
// the rim centroid on frame 0.  Throws InputError when frame 0 has no
// boundary or the vertex counts differ.
std::vector<MeshFrameMotion> MeasureMeshMotion(
    const std::vector<TriangleMesh>& frames);

}  // namespace pfdm

#endif  // PFDM_REPORT_MESH_MOTION_H_
