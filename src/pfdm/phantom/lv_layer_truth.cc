#include "pfdm/phantom/lv_layer_truth.h"

#include <cmath>
#include <functional>
#include <limits>

#include "pfdm/phantom/lv_cylinder.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

constexpr int kRows = 60;   // Of h.
constexpr int kCols = 120;  // Of longitude: 3 degrees, on sector edges.
constexpr int kSegments = 17;
constexpr double kLayerW[3] = {-1.0, 0.0, 1.0};
constexpr double kThirdBounds[4] = {-1.0, -1.0 / 3, 1.0 / 3, 1.0};
constexpr double kStep = 1e-5;  // Of h and phi (radians).
// Per cell: per layer its four neighbours (h +-, phi +-), then the four
// bounds of the thirds.
constexpr int kStride = 4 * 3 + 4;

using Body = std::function<Eigen::Vector3d(double h, double phi, double w)>;
using Points = std::vector<Eigen::Vector3d>;

int SegmentOf(double h, double lambda_deg, double cap) {
  if (h < cap) return kSegments - 1;
  const int level = h >= 2.0 / 3.0 ? 0 : h >= 1.0 / 3.0 ? 1 : 2;
  const int sectors = level == 2 ? 4 : 6;
  return level * 6 +
         static_cast<int>(std::floor(lambda_deg / 360.0 * sectors)) % sectors;
}

void AddCell(const Body& body, double h, double phi, Points* material) {
  for (double w : kLayerW) {
    material->push_back(body(h + kStep, phi, w));
    material->push_back(body(h - kStep, phi, w));
    material->push_back(body(h, phi + kStep, w));
    material->push_back(body(h, phi - kStep, w));
  }
  for (double w : kThirdBounds) material->push_back(body(h, phi, w));
}

// d/dh and d/dphi on layer k of the cell at `i` (times 2 kStep).
struct Derivatives {
  Eigen::Vector3d h, phi;
};
Derivatives At(const Points& x, int i, int k) {
  const int j = i + 4 * k;
  return {x[j] - x[j + 1], x[j + 2] - x[j + 3]};
}

double Green(double stretch) { return 100.0 * 0.5 * (stretch * stretch - 1); }

double Green(const Eigen::Vector3d& now, const Eigen::Vector3d& before) {
  return Green(now.norm() / before.norm());
}

const Eigen::Vector3d* Bounds(const Points& x, int i) { return &x[i + 4 * 3]; }

std::array<double, 3> Thirds(const Points& x, int i) {
  const Derivatives mid = At(x, i, 1);
  const Eigen::Vector3d normal = mid.h.cross(mid.phi).normalized();
  const Eigen::Vector3d* b = Bounds(x, i);
  std::array<double, 3> thickness;
  for (int k = 0; k < 3; ++k) {
    thickness[k] = std::abs((b[k + 1] - b[k]).dot(normal));
  }
  return thickness;
}

// Adds cell i's strains to `sum`, weighted by `weight`.
void AddStrains(const Points& x0, const Points& x, int i, double weight,
                LvSegmentLayers* sum) {
  const Eigen::Vector3d *b0 = Bounds(x0, i), *b = Bounds(x, i);
  sum->err_percent += weight * Green(b[3] - b[0], b0[3] - b0[0]);
  const std::array<double, 3> t0 = Thirds(x0, i), t = Thirds(x, i);
  for (int k = 0; k < 3; ++k) {
    const Derivatives before = At(x0, i, k), now = At(x, i, k);
    LvLayerValues& layer = sum->layers[k];
    layer.ecc_percent += weight * Green(now.phi, before.phi);
    layer.ell_percent += weight * Green(now.h, before.h);
    layer.thickening_percent += weight * 100.0 * (t[k] / t0[k] - 1.0);
  }
}

void Divide(double weight, LvSegmentLayers* segment) {
  const double scale =
      weight > 0.0 ? 1.0 / weight : std::numeric_limits<double>::quiet_NaN();
  segment->err_percent *= scale;
  for (LvLayerValues& layer : segment->layers) {
    for (double* value :
         {&layer.ecc_percent, &layer.ell_percent, &layer.thickening_percent}) {
      *value *= scale;
    }
  }
}

struct Cells {
  Points material;
  std::vector<int> segment;
  std::vector<double> weight;
};

Cells LayOut(const Body& body, double low, double high, double cap) {
  Cells cells;
  for (int row = 0; row < kRows; ++row) {
    const double h = low + (high - low) * (row + 0.5) / kRows;
    for (int col = 0; col < kCols; ++col) {
      const double lambda_deg = (col + 0.5) * 360.0 / kCols;
      const double phi = lambda_deg / kDegreesPerRadian - kPi;
      const int i = static_cast<int>(cells.material.size());
      AddCell(body, h, phi, &cells.material);
      const Derivatives mid = At(cells.material, i, 1);
      cells.weight.push_back(mid.h.cross(mid.phi).norm());
      cells.segment.push_back(SegmentOf(h, lambda_deg, cap));
    }
  }
  return cells;
}

std::vector<LvSegmentLayers> Measure(const Cells& cells, const Points& x0,
                                     const Points& x, int segments) {
  std::vector<LvSegmentLayers> out(segments);
  std::vector<double> weight(segments, 0.0);
  for (size_t c = 0; c < cells.segment.size(); ++c) {
    const int s = cells.segment[c];
    AddStrains(x0, x, static_cast<int>(c) * kStride, cells.weight[c], &out[s]);
    weight[s] += cells.weight[c];
  }
  for (int s = 0; s < segments; ++s) {
    out[s].segment = s + 1;
    Divide(weight[s], &out[s]);
  }
  return out;
}

}  // namespace

std::vector<std::vector<LvSegmentLayers>> MeasureLvLayerTruth(
    const LvPhantom& phantom, double apex_cap_fraction) {
  const LvPhantomOptions& options = phantom.options;
  const LvShape shape(options.shape);
  const bool cylinder_geometry = options.geometry == LvGeometry::kCylinder;
  const LvHeights band = LvRegionHeights(LvRegion::kMidventricular);
  const LvCylinder cylinder = CylinderOf(options.shape, band.low, band.high);
  Body body = [&](double h, double phi, double w) -> Eigen::Vector3d {
    if (cylinder_geometry) return cylinder.Position(h, phi, w);
    return shape.Position(shape.NuAtHeight(h * shape.base_z(), 0.0), phi, w);
  };
  const Cells cells = cylinder_geometry
                          ? LayOut(body, cylinder.low, cylinder.high, 0.0)
                          : LayOut(body, 0.0, 1.0, apex_cap_fraction);
  const int segments = apex_cap_fraction > 0.0 ? kSegments : kSegments - 1;
  std::vector<std::vector<LvSegmentLayers>> truth;
  Points x0, x(cells.material.size());
  for (int t = 0; t < options.num_frames; ++t) {
    const LvFrameMotion motion = ScenarioMotion(
        options.kinematics, t, options.num_frames, options.breathing);
    for (size_t i = 0; i < x.size(); ++i) {
      const Eigen::Vector3d& ed = cells.material[i];
      x[i] = cylinder_geometry
                 ? Eigen::Vector3d(DeformedBodyPoint(
                       options.deformation, cylinder.MaterialPoint(ed),
                       motion.progress, options.law, cylinder.LawRadii()))
                 : LvWorldPoint(shape, options.deformation, motion, ed,
                                options.law);
    }
    if (t == 0) x0 = x;
    truth.push_back(Measure(cells, x0, x, segments));
  }
  return truth;
}

}  // namespace pfdm
