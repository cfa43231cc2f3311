#include "pfdm/fit/stages/frame_points.h"

#include <algorithm>

#include "Eigen/Dense"

namespace pfdm {
namespace {

double LayerDepth(WallLayer layer) {
  return layer == WallLayer::kEndocardium  ? -1.0
         : layer == WallLayer::kEpicardium ? 1.0
                                           : 0.0;
}

}  // namespace

FramesPerId CountFramesPerId(const PointSequence& sequence) {
  FramesPerId frames_per_id;
  for (const Frame& frame : sequence.frames) {
    for (const DataPoint& p : frame.points) ++frames_per_id[p.id];
  }
  return frames_per_id;
}

FramePoints MakeFramePoints(const Frame& frame, bool reference,
                            const FramesPerId& frames_per_id,
                            const TrackedMaterial& tracked_material,
                            std::vector<MaterialPoint>* material) {
  const size_t n = frame.points.size();
  FramePoints points;
  points.index = frame.index;
  points.positions = Positions(frame);
  points.assign_depth.assign(n, false);
  points.sliding.assign(n, false);
  material->assign(n, MaterialPoint());
  for (size_t i = 0; i < n; ++i) {
    const DataPoint& p = frame.points[i];
    points.layer_w.push_back(LayerDepth(p.layer));
    points.is_tag.push_back(frames_per_id.at(p.id) > 1);
    auto it = tracked_material.find(p.id);
    if (it != tracked_material.end()) {
      (*material)[i] = it->second;
      points.tracked.push_back(i);
      continue;
    }
    points.untracked.push_back(i);
    points.sliding[i] = true;
    points.assign_depth[i] = reference && points.is_tag[i];
  }
  points.kind = reference                      ? FrameKind::kReference
                : points.untracked.size() == n ? FrameKind::kUntracked
                                               : FrameKind::kTracked;
  return points;
}

bool HasContoursBesideTags(const FramePoints& points) {
  if (points.kind != FrameKind::kTracked) return false;
  const auto labelled = [](double w) { return w != 0.0; };
  if (std::any_of(points.layer_w.begin(), points.layer_w.end(), labelled)) {
    return true;
  }
  const auto once =
      std::count(points.is_tag.begin(), points.is_tag.end(), false);
  return once > kMixedShare * points.is_tag.size();
}

std::vector<Eigen::Vector3d> Positions(const Frame& frame) {
  std::vector<Eigen::Vector3d> positions;
  positions.reserve(frame.points.size());
  for (const DataPoint& p : frame.points) positions.push_back(p.position);
  return positions;
}

Eigen::Vector3d PrincipalSpreads(const Frame& frame) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const DataPoint& p : frame.points) mean += p.position;
  mean /= static_cast<double>(frame.points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const DataPoint& p : frame.points) {
    covariance += (p.position - mean) * (p.position - mean).transpose();
  }
  covariance /= static_cast<double>(frame.points.size());
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance)
      .eigenvalues()
      .cwiseMax(0.0)
      .cwiseSqrt();
}

}  // namespace pfdm
