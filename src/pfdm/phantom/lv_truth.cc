#include "pfdm/phantom/lv_truth.h"

#include <algorithm>
#include <cmath>

#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

constexpr int kRings = 20;
constexpr int kRingPoints = 360;
// Triangulation of each closed surface: volumes within ~0.02 % (chords).
constexpr int kSurfaceRows = 96;
constexpr int kSurfaceCols = 256;
// Segment cells: 1/60 of the height by 3 degrees, so that thirds and
// sectors of 60 and 90 degrees fall on cell edges.
constexpr int kSegmentRows = 60;
constexpr int kSegmentCols = 120;
constexpr double kLayerW[3] = {-1.0, 0.0, 1.0};  // Endo, mid, epi.
constexpr int kLinePoints = 72;                  // Transmural lines per ring.

// A transmural line's material points: endocardium, epicardium, and four
// mid-wall neighbours (nu + d, nu - d, phi + d, phi - d) for its normal.
constexpr int kLineStride = 6;
constexpr double kNormalStep = 1e-4;  // Radians of nu and phi.

void AddLine(const LvShape& shape, double nu, double phi,
             std::vector<Eigen::Vector3d>* material) {
  material->push_back(shape.Position(nu, phi, -1.0));
  material->push_back(shape.Position(nu, phi, 1.0));
  material->push_back(shape.Position(nu + kNormalStep, phi, 0.0));
  material->push_back(shape.Position(nu - kNormalStep, phi, 0.0));
  material->push_back(shape.Position(nu, phi + kNormalStep, 0.0));
  material->push_back(shape.Position(nu, phi - kNormalStep, 0.0));
}

// The wall's thickness across the line: endo-to-epi along the mid-wall's
// normal there (what an echo or CMR chord perpendicular to the wall reads).
double Thickness(const std::vector<Eigen::Vector3d>& world, int i) {
  const Eigen::Vector3d normal =
      (world[i + 2] - world[i + 3]).cross(world[i + 4] - world[i + 5]);
  return std::abs((world[i + 1] - world[i]).dot(normal.normalized()));
}

// Mean over `count` lines from `begin` of T / T0 - 1.
double LineStretch(const std::vector<Eigen::Vector3d>& world0,
                   const std::vector<Eigen::Vector3d>& world, int begin,
                   int count) {
  double sum = 0.0;
  for (int i = begin; i < begin + kLineStride * count; i += kLineStride) {
    sum += Thickness(world, i) / Thickness(world0, i) - 1.0;
  }
  return sum / count;
}

using Points = std::vector<Eigen::Vector3d>;

Eigen::Vector3d Centroid(const Points& points, int begin, int count) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int i = begin; i < begin + count; ++i) sum += points[i];
  return sum / count;
}

double MeanDistance(const Points& points, int begin, int count,
                    const Eigen::Vector3d& centre) {
  double sum = 0.0;
  for (int i = begin; i < begin + count; ++i) {
    sum += (points[i] - centre).norm();
  }
  return sum / count;
}

// Angle (radians) from a0 to a about `axis`, both projected across it.
double TurnAbout(const Eigen::Vector3d& axis, const Eigen::Vector3d& a0,
                 const Eigen::Vector3d& a) {
  const Eigen::Vector3d q0 = a0 - a0.dot(axis) * axis;
  const Eigen::Vector3d q = a - a.dot(axis) * axis;
  return std::atan2(axis.dot(q0.cross(q)), q0.dot(q));
}

int SegmentOf(double h, double lambda_deg) {
  // Basal 1-6, mid 7-12, apical 13-16, as report/wall_motion.
  const int level = h >= 2.0 / 3.0 ? 0 : h >= 1.0 / 3.0 ? 1 : 2;
  const int sectors = level == 2 ? 4 : 6;
  const int first = level * 6;
  return first +
         static_cast<int>(std::floor(lambda_deg / 360.0 * sectors)) % sectors;
}

std::string SegmentName(int segment) {
  static const char* const kLevels[] = {"basal", "mid", "apical"};
  const int level = segment / 6;
  return std::string(kLevels[level]) + " " +
         std::to_string(segment - 6 * level + 1);
}

}  // namespace

std::vector<double> LvRingHeights() {
  std::vector<double> heights;
  for (int i = 1; i <= kRings; ++i) heights.push_back(i / 20.0);
  return heights;
}

double LvRingValueAt(const std::vector<double>& values, double h) {
  // Rings at h = (i + 1) / kRings; segment i runs from ring i to ring i + 1.
  const double position = std::clamp(h, 0.0, 1.0) * kRings - 1.0;
  const int i =
      std::clamp(static_cast<int>(std::floor(position)), 0, kRings - 2);
  const double t = position - i;
  return (1.0 - t) * values[i] + t * values[i + 1];
}

LvTruthMeter::LvTruthMeter(const LvShape& shape) {
  material_.push_back(Eigen::Vector3d::Zero());  // Mid-wall apex pole.
  for (int layer = 0; layer < 3; ++layer) {
    for (double h : LvRingHeights()) {
      ring_begin_[layer].push_back(static_cast<int>(material_.size()));
      const double nu = shape.NuAtHeight(h * shape.base_z(), kLayerW[layer]);
      for (int i = 0; i < kRingPoints; ++i) {
        const double phi = -kPi + 2.0 * kPi * i / kRingPoints;
        material_.push_back(shape.Position(nu, phi, kLayerW[layer]));
      }
    }
    AddGrid(shape, kLayerW[layer], &surface_[layer]);
  }
  line_begin_ = static_cast<int>(material_.size());
  for (double h : LvRingHeights()) {
    const double nu = shape.NuAtHeight(h * shape.base_z(), 0.0);
    for (int i = 0; i < kLinePoints; ++i) {
      AddLine(shape, nu, -kPi + 2.0 * kPi * i / kLinePoints, &material_);
    }
  }
  // Segment cells on the mid-wall, weighted by their ED area: per unit of h
  // and phi, r |dX/dh| in the meridian plane.
  segment_begin_ = static_cast<int>(material_.size());
  const double step = 1e-6;
  for (int row = 0; row < kSegmentRows; ++row) {
    const double h = (row + 0.5) / kSegmentRows;
    const double nu = shape.NuAtHeight(h * shape.base_z(), 0.0);
    const Eigen::Vector3d below = shape.Position(
        shape.NuAtHeight((h - step) * shape.base_z(), 0.0), 0.0, 0.0);
    const Eigen::Vector3d above = shape.Position(
        shape.NuAtHeight((h + step) * shape.base_z(), 0.0), 0.0, 0.0);
    const double weight =
        shape.Position(nu, 0.0, 0.0).x() * (above - below).norm() / (2 * step);
    for (int col = 0; col < kSegmentCols; ++col) {
      const double lambda_deg = (col + 0.5) * 360.0 / kSegmentCols;
      material_.push_back(
          shape.Position(nu, lambda_deg / kDegreesPerRadian - kPi, 0.0));
      segment_weight_.push_back(weight);
      segment_of_.push_back(SegmentOf(h, lambda_deg));
    }
  }
  cell_line_begin_ = static_cast<int>(material_.size());
  for (int row = 0; row < kSegmentRows; ++row) {
    const double nu =
        shape.NuAtHeight((row + 0.5) / kSegmentRows * shape.base_z(), 0.0);
    for (int col = 0; col < kSegmentCols; ++col) {
      AddLine(shape, nu, (col + 0.5) * 2.0 * kPi / kSegmentCols - kPi,
              &material_);
    }
  }
}

void LvTruthMeter::AddGrid(const LvShape& shape, double w, Grid* grid) {
  grid->begin = static_cast<int>(material_.size());
  grid->rows = kSurfaceRows;
  grid->cols = kSurfaceCols;
  const double base_nu = shape.BaseNu(w);
  material_.push_back(shape.Position(0.0, 0.0, w));
  for (int row = 1; row <= kSurfaceRows; ++row) {
    const double nu = base_nu * row / kSurfaceRows;
    for (int col = 0; col < kSurfaceCols; ++col) {
      material_.push_back(
          shape.Position(nu, -kPi + 2.0 * kPi * col / kSurfaceCols, w));
    }
  }
}

namespace {

// Volume inside a pole-and-rows grid closed by the plane of its last row,
// by the divergence theorem about the last row's centroid (the lid's
// triangles then add nothing).
double ClosedGridVolume(const Points& world, int begin, int rows, int cols) {
  auto at = [&](int row, int col) -> const Eigen::Vector3d& {
    return world[begin + 1 + (row - 1) * cols + (col % cols)];
  };
  const Eigen::Vector3d o =
      Centroid(world, begin + 1 + (rows - 1) * cols, cols);
  auto tetra = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                   const Eigen::Vector3d& c) {
    return (a - o).dot((b - o).cross(c - o)) / 6.0;
  };
  double volume = 0.0;
  for (int col = 0; col < cols; ++col) {
    volume += tetra(world[begin], at(1, col), at(1, col + 1));
    for (int row = 1; row < rows; ++row) {
      volume += tetra(at(row, col), at(row + 1, col), at(row + 1, col + 1));
      volume += tetra(at(row, col), at(row + 1, col + 1), at(row, col + 1));
    }
  }
  return std::abs(volume);
}

}  // namespace

LvFrameTruth LvTruthMeter::Measure(const Points& world0,
                                   const Points& world) const {
  LvFrameTruth truth;
  const int base_ring = ring_begin_[1].back();
  const Eigen::Vector3d base0 = Centroid(world0, base_ring, kRingPoints);
  const Eigen::Vector3d axis0 = (base0 - world0[0]).normalized();
  const double length0 = (base0 - world0[0]).norm();
  truth.length_mm = (Centroid(world, base_ring, kRingPoints) - world[0]).norm();
  truth.longitudinal_shortening_percent =
      100.0 * (1.0 - truth.length_mm / length0);

  LvLayerRings* layers[3] = {&truth.endo, &truth.midwall, &truth.epi};
  for (int layer = 0; layer < 3; ++layer) {
    for (int begin : ring_begin_[layer]) {
      const Eigen::Vector3d c0 = Centroid(world0, begin, kRingPoints);
      const Eigen::Vector3d c = Centroid(world, begin, kRingPoints);
      double turn = 0.0;
      for (int i = begin; i < begin + kRingPoints; ++i) {
        turn += TurnAbout(axis0, world0[i] - c0, world[i] - c);
      }
      layers[layer]->rotation_deg.push_back(kDegreesPerRadian * turn /
                                            kRingPoints);
      layers[layer]->radial_contraction_percent.push_back(
          100.0 * (1.0 - MeanDistance(world, begin, kRingPoints, c) /
                             MeanDistance(world0, begin, kRingPoints, c0)));
    }
  }

  const std::vector<double>& rotation = truth.midwall.rotation_deg;
  truth.apex_rotation_deg = LvRingValueAt(rotation, 0.0);
  truth.base_rotation_deg = rotation.back();
  truth.net_twist_deg = truth.base_rotation_deg - truth.apex_rotation_deg;
  for (double c : truth.midwall.radial_contraction_percent) {
    truth.mean_radial_contraction_percent += c / kRings;
  }

  double volumes[3];
  for (int layer = 0; layer < 3; ++layer) {
    const Grid& grid = surface_[layer];
    volumes[layer] =
        ClosedGridVolume(world, grid.begin, grid.rows, grid.cols) / 1000.0;
  }
  truth.endo_volume_ml = volumes[0];
  truth.volume_ml = volumes[1];
  truth.epi_volume_ml = volumes[2];
  truth.myocardial_volume_ml = volumes[2] - volumes[0];
  for (int ring = 0; ring < kRings; ++ring) {
    truth.wall_thickening_percent.push_back(
        100.0 * LineStretch(world0, world,
                            line_begin_ + kLineStride * kLinePoints * ring,
                            kLinePoints));
  }

  constexpr int kSegments = 16;
  std::vector<double> weight(kSegments, 0.0), turn(kSegments, 0.0),
      contraction(kSegments, 0.0), thickening(kSegments, 0.0);
  for (int row = 0; row < kSegmentRows; ++row) {
    const int begin = segment_begin_ + row * kSegmentCols;
    const Eigen::Vector3d c0 = Centroid(world0, begin, kSegmentCols);
    const Eigen::Vector3d c = Centroid(world, begin, kSegmentCols);
    for (int col = 0; col < kSegmentCols; ++col) {
      const int cell = row * kSegmentCols + col;
      const int i = begin + col;
      const int s = segment_of_[cell];
      const double wt = segment_weight_[cell];
      weight[s] += wt;
      turn[s] += wt * TurnAbout(axis0, world0[i] - c0, world[i] - c);
      contraction[s] +=
          wt * (1.0 - (world[i] - c).norm() / (world0[i] - c0).norm());
      thickening[s] +=
          wt *
          LineStretch(world0, world, cell_line_begin_ + kLineStride * cell, 1);
    }
  }
  for (int s = 0; s < kSegments; ++s) {
    LvSegmentTruth segment;
    segment.segment = s + 1;
    segment.name = SegmentName(s);
    segment.rotation_deg = kDegreesPerRadian * turn[s] / weight[s];
    segment.radial_contraction_percent = 100.0 * contraction[s] / weight[s];
    segment.wall_thickening_percent = 100.0 * thickening[s] / weight[s];
    truth.segments.push_back(segment);
  }
  return truth;
}

}  // namespace pfdm
