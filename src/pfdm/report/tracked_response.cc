#include "pfdm/report/tracked_response.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "Eigen/Dense"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/report/number_uncertainty.h"

namespace pfdm {
namespace {

using Kind = CovarianceEntry::Kind;

bool Applies(const SequenceFit& fit, size_t t) {
  if (fit.ed_frame != 0 || t == 0 || t >= fit.frames.size()) return false;
  const FrameFit& frame = fit.frames[t];
  const FrameCovariance& own = frame.covariance;
  const FrameCovariance& reference = fit.frames[0].covariance;
  return frame.kind == FrameKind::kTracked && !frame.mixed &&
         !frame.material.empty() && own.computed && reference.computed &&
         own.unit_covariance.rows() == static_cast<int>(own.entries.size());
}

// Frame t's global model: the covariance's, at whose solution the local
// field (fitted after it, held) was not yet there, and the one ED's
// material points were found on.
Model GlobalModel(const SequenceFit& fit, size_t t) {
  Model model = fit.ModelAt(static_cast<int>(t));
  model.state.local = LocalField();
  return model;
}

// Every tag up to kMaxResponseTags, else every stride-th.
std::vector<MaterialPoint> ResponseTags(
    const std::vector<MaterialPoint>& material, std::vector<size_t>* index) {
  const size_t stride = std::max<size_t>(
      1, (material.size() + kMaxResponseTags - 1) / kMaxResponseTags);
  std::vector<MaterialPoint> tags;
  for (size_t i = 0; i < material.size(); i += stride) {
    tags.push_back(material[i]);
    index->push_back(i);
  }
  return tags;
}

// dx/dm at m, by central differences: the columns u, v and (`columns` 3)
// w.
Eigen::MatrixXd MaterialJacobian(const Model& model, const MaterialPoint& m,
                                 int columns) {
  constexpr double kStep = 1e-5;
  Eigen::MatrixXd jacobian(3, columns);
  for (int c = 0; c < columns; ++c) {
    MaterialPoint plus = m, minus = m;
    double* plus_c = c == 0 ? &plus.u : c == 1 ? &plus.v : &plus.w;
    double* minus_c = c == 0 ? &minus.u : c == 1 ? &minus.v : &minus.w;
    *plus_c += kStep;
    *minus_c -= kStep;
    jacobian.col(c) = (model.WorldPoint(plus.u, plus.v, plus.w) -
                       model.WorldPoint(minus.u, minus.v, minus.w)) /
                      (2.0 * kStep);
  }
  return jacobian;
}

// Per tag, c_i = -K_i L_i^+ dx_i's matrix -K_i L_i^+ (3 x 3), split into
// the part through the tag's (u, v) and the part through its depth w (0
// with two columns).
struct RelabelMap {
  Eigen::Matrix3d along_surface, through_wall;
};

std::vector<RelabelMap> RelabelMaps(const Model& reference, const Model& frame,
                                    const std::vector<MaterialPoint>& tags,
                                    int columns) {
  std::vector<RelabelMap> maps;
  maps.reserve(tags.size());
  for (const MaterialPoint& m : tags) {
    const Eigen::MatrixXd along = MaterialJacobian(reference, m, columns);
    const Eigen::MatrixXd inverse =
        along.completeOrthogonalDecomposition().pseudoInverse();
    const Eigen::MatrixXd follow = -MaterialJacobian(frame, m, columns);
    RelabelMap map;
    map.along_surface = follow.leftCols(2) * inverse.topRows(2);
    map.through_wall = columns == 3
                           ? Eigen::Matrix3d(follow.col(2) * inverse.row(2))
                           : Eigen::Matrix3d::Zero();
    maps.push_back(map);
  }
  return maps;
}

// d (tags' world points) / d (covariance coordinate) of `model`, one
// column a coordinate (3 rows a tag): NumberJacobian's central differences
// of the points; `skip_pose`'s pose columns set to 0.
Eigen::MatrixXd PointJacobian(const Model& model,
                              const FrameCovariance& covariance,
                              const std::vector<MaterialPoint>& tags,
                              bool skip_pose) {
  const NumbersOf points = [&tags](const Model& moved) {
    std::vector<double> flat;
    flat.reserve(3 * tags.size());
    for (const Eigen::Vector3d& x : WorldPoints(moved, tags)) {
      flat.insert(flat.end(), {x.x(), x.y(), x.z()});
    }
    return flat;
  };
  Eigen::MatrixXd jacobian = NumberJacobian(model, covariance, points);
  for (size_t j = 0; skip_pose && j < covariance.entries.size(); ++j) {
    const Kind kind = covariance.entries[j].kind;
    if (kind == Kind::kCenter || kind == Kind::kRotation) {
      jacobian.col(static_cast<Eigen::Index>(j)).setZero();
    }
  }
  return jacobian;
}

}  // namespace

TrackedResponse MeasureTrackedResponse(const SequenceFit& fit, size_t t) {
  if (!Applies(fit, t)) return {};
  const FrameFit& frame = fit.frames[t];
  const Model reference = GlobalModel(fit, 0);
  const Model model = GlobalModel(fit, t);
  std::vector<size_t> index;
  const std::vector<MaterialPoint> tags = ResponseTags(frame.material, &index);
  // A held depth is where frame 0's model put the tag across the wall;
  // ranked anew, or on a surface, the tag keeps its depth.
  const bool through_wall = fit.config.Solid() && frame.depths_held;
  const std::vector<RelabelMap> maps =
      RelabelMaps(reference, model, tags, through_wall ? 3 : 2);
  // The residuals' change per unit step of frame 0's coordinates, weighed by
  // the loss and by each tag's share of the frame's tags.
  const Eigen::MatrixXd moved = PointJacobian(
      reference, fit.frames[0].covariance, tags, /*skip_pose=*/true);
  Eigen::MatrixXd along(moved.rows(), moved.cols());
  Eigen::MatrixXd across(through_wall ? moved.rows() : 0, moved.cols());
  const double share = static_cast<double>(frame.material.size()) /
                       static_cast<double>(tags.size());
  const bool weighed = frame.loss_weights.size() == frame.material.size();
  for (size_t i = 0; i < tags.size(); ++i) {
    const double weight =
        share * (weighed ? frame.loss_weights[index[i]] : 1.0);
    const auto rows = moved.middleRows<3>(3 * i);
    along.middleRows<3>(3 * i) = weight * maps[i].along_surface * rows;
    if (through_wall) {
      across.middleRows<3>(3 * i) = weight * maps[i].through_wall * rows;
    }
  }
  const Eigen::MatrixXd data =
      PointJacobian(model, frame.covariance, tags, /*skip_pose=*/false);
  const Eigen::MatrixXd& unit = frame.covariance.unit_covariance;
  TrackedResponse response;
  response.along_surface = -unit * (data.transpose() * along);
  if (through_wall) response.through_wall = -unit * (data.transpose() * across);
  return response;
}

}  // namespace pfdm
