#include "pfdm/io/partial_rings.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "Eigen/Geometry"
#include "Eigen/QR"
#include "Eigen/SVD"

namespace pfdm {
namespace {

constexpr double kPi = 3.14159265358979323846;

bool IsShortAxis(const std::string& contour) {
  return contour.rfind("SAX_", 0) == 0;
}

std::string TypeOf(const std::string& contour) {
  return contour.substr(0, contour.find(' '));
}

// Points less their mean, as rows, and their principal directions
// (svd.matrixV()'s columns, the largest spread first).
struct Centred {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  Eigen::MatrixXd rows;
  Eigen::Matrix3d directions;
};
Centred CentredPoints(const std::vector<Eigen::Vector3d>& points) {
  Centred c;
  for (const Eigen::Vector3d& p : points) c.mean += p;
  c.mean /= static_cast<double>(points.size());
  c.rows.resize(points.size(), 3);
  for (size_t i = 0; i < points.size(); ++i) {
    c.rows.row(i) = points[i] - c.mean;
  }
  c.directions =
      Eigen::JacobiSVD<Eigen::MatrixXd>(c.rows, Eigen::ComputeFullV).matrixV();
  return c;
}

// The least-squares line through `points`: a point on it and its direction.
struct Line {
  Eigen::Vector3d point;
  Eigen::Vector3d direction;
};
Line FitLine(const std::vector<Eigen::Vector3d>& points) {
  const Centred c = CentredPoints(points);
  return {c.mean, c.directions.col(0)};
}

// The largest angle between neighbouring directions, degrees.
double LargestGap(std::vector<double> angles) {
  std::sort(angles.begin(), angles.end());
  double gap = angles.front() + 2.0 * kPi - angles.back();
  for (size_t i = 1; i < angles.size(); ++i) {
    gap = std::max(gap, angles[i] - angles[i - 1]);
  }
  return gap * 180.0 / kPi;
}

// A frame's short-axis rings of one type, from apex to base.
std::vector<RingCircle> RingsFromApex(
    const std::map<std::string, std::vector<Eigen::Vector3d>>& rings) {
  std::vector<RingCircle> circles;
  std::vector<Eigen::Vector3d> centres;
  for (const auto& [contour, ring] : rings) {
    if (ring.size() < 3) continue;
    circles.push_back(FitRingCircle(ring));
    circles.back().contour = contour;
    centres.push_back(circles.back().centre);
  }
  // Which end is the base needs a ring between each end and the middle.
  if (circles.size() < kMinRingsJudged) return {};
  const Eigen::Vector3d d = FitLine(centres).direction;
  std::sort(circles.begin(), circles.end(),
            [&](const RingCircle& a, const RingCircle& b) {
              return a.centre.dot(d) < b.centre.dot(d);
            });
  // The ventricle is wider next to its base than next to its apex.
  if (circles[1].radius > circles[circles.size() - 2].radius) {
    std::reverse(circles.begin(), circles.end());
  }
  return circles;
}

// A type's most basal ring, where the line through the other rings'
// centres crosses its plane, and whether it lies beside that line.
struct BasalRing {
  std::string contour;
  Eigen::Vector3d through = Eigen::Vector3d::Zero();
  bool beside_axis = false;
};
BasalRing JudgeBasalRing(
    const std::map<std::string, std::vector<Eigen::Vector3d>>& rings) {
  const std::vector<RingCircle> stack = RingsFromApex(rings);
  if (stack.empty()) return {};
  const RingCircle& base = stack.back();
  std::vector<Eigen::Vector3d> axis_centres;
  for (size_t k = 0; k + 1 < stack.size(); ++k) {
    axis_centres.push_back(stack[k].centre);
  }
  const Line axis = FitLine(axis_centres);
  const Eigen::Vector3d normal = base.e1.cross(base.e2);
  const double along =
      (base.centre - axis.point).dot(normal) / axis.direction.dot(normal);
  BasalRing basal{base.contour, axis.point + along * axis.direction, false};
  const double gap = LargestGapDeg(rings.at(base.contour), base, basal.through);
  const double off_axis = (basal.through - base.centre).norm() / base.radius;
  basal.beside_axis = gap > kPartialRingGapDeg && off_axis > kBesideAxisRadii;
  return basal;
}

std::string SliceOf(const std::string& contour) {
  const size_t space = contour.find(' ');
  return space == std::string::npos ? "" : contour.substr(space + 1);
}

}  // namespace

RingCircle FitRingCircle(const std::vector<Eigen::Vector3d>& ring) {
  const Centred c = CentredPoints(ring);
  const Eigen::MatrixXd& centred = c.rows;
  RingCircle circle;
  circle.e1 = c.directions.col(0);
  circle.e2 = c.directions.col(1);
  // Kasa's algebraic fit, x^2 + y^2 + D x + E y + F = 0: linear in D, E, F.
  Eigen::MatrixXd a(ring.size(), 3);
  Eigen::VectorXd b(ring.size());
  for (size_t i = 0; i < ring.size(); ++i) {
    const double x = centred.row(i).dot(circle.e1);
    const double y = centred.row(i).dot(circle.e2);
    a.row(i) << x, y, 1.0;
    b(i) = -(x * x + y * y);
  }
  const Eigen::Vector3d def = a.colPivHouseholderQr().solve(b);
  const double cx = -0.5 * def(0), cy = -0.5 * def(1);
  circle.centre = c.mean + cx * circle.e1 + cy * circle.e2;
  circle.radius = std::sqrt(std::max(0.0, cx * cx + cy * cy - def(2)));
  return circle;
}

double LargestGapDeg(const std::vector<Eigen::Vector3d>& ring,
                     const RingCircle& plane, const Eigen::Vector3d& from) {
  if (ring.size() < 2) return 360.0;
  std::vector<double> angles;
  for (const Eigen::Vector3d& p : ring) {
    const Eigen::Vector3d d = p - from;
    angles.push_back(std::atan2(d.dot(plane.e2), d.dot(plane.e1)));
  }
  return LargestGap(angles);
}

void LeaveOutPartialRings(int frame, const std::vector<std::string>& contours,
                          std::vector<DataPoint>* points,
                          std::vector<LeftOutContour>* left_out) {
  std::map<std::string, std::map<std::string, std::vector<Eigen::Vector3d>>>
      rings_per_type;
  for (size_t i = 0; i < points->size(); ++i) {
    if (IsShortAxis(contours[i])) {
      rings_per_type[TypeOf(contours[i])][contours[i]].push_back(
          (*points)[i].position);
    }
  }
  // The slices whose basal ring of some type lies beside the axis, and
  // where the axis crosses them.
  std::map<std::string, Eigen::Vector3d> slices;
  for (const auto& [type, rings] : rings_per_type) {
    const BasalRing basal = JudgeBasalRing(rings);
    if (basal.beside_axis) slices[SliceOf(basal.contour)] = basal.through;
  }
  if (slices.empty()) return;
  std::set<std::string> dropped;
  for (const auto& [type, rings] : rings_per_type) {
    for (const auto& [contour, ring] : rings) {
      const auto slice = slices.find(SliceOf(contour));
      if (slice == slices.end()) continue;
      dropped.insert(contour);
      const double gap =
          ring.size() < 3
              ? 360.0
              : LargestGapDeg(ring, FitRingCircle(ring), slice->second);
      left_out->push_back(
          {frame, contour, static_cast<int>(ring.size()), 360.0 - gap});
    }
  }
  std::vector<DataPoint> kept;
  for (size_t i = 0; i < points->size(); ++i) {
    if (dropped.count(contours[i]) == 0) kept.push_back((*points)[i]);
  }
  *points = std::move(kept);
}

}  // namespace pfdm
