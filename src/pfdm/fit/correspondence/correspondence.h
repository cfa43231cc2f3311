// Closest material points: the (u, v) a data point is tied to.
#ifndef PFDM_FIT_CORRESPONDENCE_CORRESPONDENCE_H_
#define PFDM_FIT_CORRESPONDENCE_CORRESPONDENCE_H_

#include <cstdint>
#include <vector>

#include "Eigen/Core"
#include "pfdm/model/model.h"

namespace pfdm {

struct MaterialPoint {
  double u = 0.0;
  double v = 0.0;
  double w = 0.0;  // Transmural: -1 endocardium, 0 mid-wall, +1 epicardium.
};

// model.WorldPoint at each material point, in batches (world_points.h).
std::vector<Eigen::Vector3d> WorldPoints(
    const Model& model, const std::vector<MaterialPoint>& material);

// Model point minus data point at each material point (mm): points[i]'s
// residual at material[i].
std::vector<Eigen::Vector3d> Residuals(
    const Model& model, const std::vector<Eigen::Vector3d>& points,
    const std::vector<MaterialPoint>& material);

// Each material point's height along the model's long axis (axis 3, apex
// to base) in mm, from the world origin.
std::vector<double> AxialHeights(const Model& model,
                                 const std::vector<MaterialPoint>& material);

// The model's world-space point x(u, v, w), for any scalar (a Jet when u
// and v are differentiated).
template <typename T>
Eigen::Matrix<T, 3, 1> WorldPointAt(const Model& model, const T& u, const T& v,
                                    double w = 0.0);

// Unit outward normal of the model's surface w at (u, v), world frame: out
// of the cavity.  At the apex pole, where d/dv vanishes, the axis direction
// -z.
Eigen::Vector3d SurfaceNormal(const Model& model, double u, double v,
                              double w = 0.0);

// SurfaceNormal at each material point and, when surface_points is given,
// the model points there, both from one evaluation per point.
std::vector<Eigen::Vector3d> SurfaceNormals(
    const Model& model, const std::vector<MaterialPoint>& material,
    std::vector<Eigen::Vector3d>* surface_points = nullptr);

// dx/du and dx/dv of the model's surface w at each material point (world
// frame, mm per radian), in the columns of each matrix.
std::vector<Eigen::Matrix<double, 3, 2>> SurfaceTangents(
    const Model& model, const std::vector<MaterialPoint>& material);

// Whether a sliding point at this material point pulls along the surface's
// normal (point-to-plane): below the rim (u < u_max).  On the rim the plane
// says nothing about how far past it the point lies, so it pulls with its
// whole vector.
bool PullsAlongNormal(const ModelConfig& config, const MaterialPoint& at);

// The normals along which sliding points pull, in one SurfaceNormals batch:
// SurfaceNormal at material[i] for the points with sliding[i] that
// PullsAlongNormal, zero for the others.
std::vector<Eigen::Vector3d> SlidingNormals(
    const Model& model, const std::vector<MaterialPoint>& material,
    const std::vector<bool>& sliding);

struct CorrespondenceOptions {
  // Threads that share the points, taking blocks of them as they free up;
  // the result does not depend on it.
  int num_threads = 1;
  // A refinement step that would move the model point by less than this
  // (mm) ends the search for that point; 0 runs every step until none
  // improves.  What is left is a fraction of it, far below the rounds'
  // tolerance (FitOptions::correspondence_tolerance_mm, 0.05 mm) and the
  // data's noise; 1e-8 mm cost a point 4.3-4.7 evaluations against 3.0-3.2
  // (a 50,000-tag frame 0).
  double step_tolerance_mm = 1e-4;
  // The surface w each point is sought on (empty: the mid-wall, w = 0).
  std::vector<double> surfaces;
  // Where each point's search may start instead of the grid's nearest
  // sample, when nearer than it and on the same surface: the material
  // points of the round before (empty: none).  After a solve has moved the
  // model a little, a point's old material point is a step or two from its
  // new one, where the grid's sample is five or more.
  std::vector<MaterialPoint> hints;
  // The same search with ceres::Jet derivatives, as before the closed-form
  // ones: slower, for tests and the benchmark's comparison; always for
  // points off the mid-wall (w != 0) and for a model with a local field,
  // which the closed form does not cover.
  bool jet_derivatives = false;
  // When set, the number of surface evaluations (each with its derivatives
  // in u and v) is added to it: the search's cost, counted.
  std::int64_t* evaluations = nullptr;
};

// For each point, the (u, v) in [u_min, u_max] x [-pi, pi) whose model point
// on its surface w is nearest: the nearest sample of a (u, v) grid of the
// mid-wall, then a few damped Newton steps on |x(u, v, w) - p|^2 with the
// surface's derivatives (in closed form on the mid-wall of a model without
// a local field) and its curvature learnt from the steps.  model_points,
// when given, receives their model points; normals their SurfaceNormal,
// from the search's last evaluation (equal to SurfaceNormal's but for
// CorrespondenceOptions::jet_derivatives' round-off).
std::vector<MaterialPoint> ClosestMaterialPoints(
    const Model& model, const std::vector<Eigen::Vector3d>& points,
    const CorrespondenceOptions& options = {},
    std::vector<Eigen::Vector3d>* model_points = nullptr,
    std::vector<Eigen::Vector3d>* normals = nullptr);

}  // namespace pfdm

#endif  // PFDM_FIT_CORRESPONDENCE_CORRESPONDENCE_H_
