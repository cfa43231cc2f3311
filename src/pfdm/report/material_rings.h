// Rings of material points (u fixed, v sampled) of fitted frames, measured
// in world coordinates: what a clinical number means does not depend on how
// the parameter functions and the pose share the motion.
#ifndef PFDM_REPORT_MATERIAL_RINGS_H_
#define PFDM_REPORT_MATERIAL_RINGS_H_

#include <vector>

#include "Eigen/Core"
#include "pfdm/model/model.h"

namespace pfdm {

// Samples per material ring: equal steps of v.
constexpr int kRingSamples = 72;

struct MaterialRing {
  std::vector<Eigen::Vector3d> points;  // At v = -pi + 2 pi (j + 0.5) / n.
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
};

// The ring at u on the solid's surface w (model/transmural.h; 0: mid-wall).
MaterialRing SampleRing(const Model& model, double u,
                        int samples = kRingSamples, double w = 0.0);

// Mean distance of the ring's points from its centroid.
double MeanRadius(const MaterialRing& ring);

// Mean over the ring's points of the angle (radians), right-handed about
// `axis` (unit), by which each point turned about its ring's centroid from
// `from` to `to`, both projected on the plane normal to the axis.
double MeanRotation(const MaterialRing& from, const MaterialRing& to,
                    const Eigen::Vector3d& axis);

// The signed angle, right-handed about `axis`, from a to b projected on the
// plane normal to the axis.
double AngleAbout(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                  const Eigen::Vector3d& axis);

// A solid's wall thickness (mm) at the material point (u, v): the vector
// from its endocardial to its epicardial point, (u, v, -1) to (u, v, +1),
// along the normal of the layer w = 0 there, as a chord perpendicular to
// the wall reads it.
double WallThickness(const Model& model, double u, double v);
// The same at a material point whose endocardial and epicardial points
// are endo and epi and whose layer w = 0 has tangents dx/du, dx/dv there:
// the regional samples take a ring's walls in a batch each (SampleRing at
// w = -1 and +1) and the tangents in closed form, where two model points
// apiece were a tenth of a solid's analysis.  At a pole, where the
// tangents give no normal, WallThickness(model, u, v).
double WallThickness(const Model& model, double u, double v,
                     const Eigen::Vector3d& endo, const Eigen::Vector3d& epi,
                     const Eigen::Vector3d& xu, const Eigen::Vector3d& xv);

// The mean of WallThickness around the material ring at u (kRingSamples
// points).
double MeanWallThickness(const Model& model, double u);

// Height of ring u along the reference model's axis in its model frame:
// a0 a3 sin u + e3o, which bending does not move (its ring mean is zero).
double RingHeight(const Model& model, double u);

// The u of the material ring at height fraction h (0 apex, 1 base rim) of
// the reference model's apex-to-base length.
double RingAtHeightFraction(const Model& reference, double h);

// The u of surface w's material ring whose centroid sits at the height of
// the mid-wall ring at fraction h (so endocardial, mid-wall and epicardial
// rings at one h share a short-axis plane on frame 0, as a slice's rings
// do).  w = 0: RingAtHeightFraction.  Clamped to [u_min, u_max].
double RingAtHeightFraction(const Model& reference, double h, double w);

// The reference frame's long axis in world coordinates (apex to base).
Eigen::Vector3d LongAxis(const Model& model);

}  // namespace pfdm

#endif  // PFDM_REPORT_MATERIAL_RINGS_H_
