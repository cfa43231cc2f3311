#include "pfdm/report/layer_strain.h"

#include <cmath>
#include <limits>
#include <optional>

#include "pfdm/report/surface_strain.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

// A few dozen samples per segment in each layer: equal steps in sin u and
// v, the pole never sampled (as wall_motion's samples).
constexpr int kLatitudes = 36;
constexpr int kLongitudes = 72;
// Central differences of the world point: the tangents within 1e-9 of
// their size, and no Jets through the local field.
constexpr double kStep = 1e-5;
constexpr double kThirdBounds[kWallLayers + 1] = {-1.0, -1.0 / 3, 1.0 / 3, 1.0};

struct Tangents {
  Eigen::Vector3d xu, xv;
};

// The functions at a sample's ring and its two neighbours in u, which the
// ring's samples share (FunctionsAt costs more than the point).
struct Ring {
  Ring(const Model& model, double u)
      : model(model),
        u(u),
        at(model.FunctionsAt(u)),
        above(model.FunctionsAt(u + kStep)),
        below(model.FunctionsAt(u - kStep)) {}
  Eigen::Vector3d Point(double v, double w) const {
    return model.WorldPointWith(at, u, v, w);
  }
  Tangents TangentsAt(double v, double w) const {
    const double scale = 0.5 / kStep;
    return {(model.WorldPointWith(above, u + kStep, v, w) -
             model.WorldPointWith(below, u - kStep, v, w)) *
                scale,
            (Point(v + kStep, w) - Point(v - kStep, w)) * scale};
  }
  const Model& model;
  double u;
  FunctionValues at, above, below;
};

// The thirds' bounds across the wall at (u, v), endocardium first.
using Bounds = std::array<Eigen::Vector3d, kWallLayers + 1>;
Bounds ThirdBounds(const Ring& ring, double v) {
  Bounds bounds;
  for (int k = 0; k <= kWallLayers; ++k) {
    bounds[k] = ring.Point(v, kThirdBounds[k]);
  }
  return bounds;
}

// Each third's thickness along `normal` (unit).
std::array<double, kWallLayers> ThirdThicknesses(
    const Bounds& bounds, const Eigen::Vector3d& normal) {
  std::array<double, kWallLayers> thickness;
  for (int k = 0; k < kWallLayers; ++k) {
    thickness[k] = std::abs((bounds[k + 1] - bounds[k]).dot(normal));
  }
  return thickness;
}

// The reference's share of sample (u, v): region, area weight (per unit of
// sin u and v, the mid-wall's), tangents, chord, thirds.
LayerSamples::Sample ReferenceSample(const Ring& ring, double v,
                                     const RegionLayout& layout) {
  LayerSamples::Sample sample;
  sample.u = ring.u;
  sample.v = v;
  sample.region = AssignRegion(ring.model, ring.u, v, layout);
  for (int k = 0; k < kWallLayers; ++k) {
    const Tangents at = ring.TangentsAt(v, kLayerDepth[k]);
    sample.xu[k] = at.xu;
    sample.xv[k] = at.xv;
  }
  const Eigen::Vector3d area = sample.xu[1].cross(sample.xv[1]);
  sample.weight = area.norm() / std::cos(ring.u);
  const Bounds bounds = ThirdBounds(ring, v);
  sample.chord = (bounds[kWallLayers] - bounds[0]).norm();
  sample.third_thickness = ThirdThicknesses(bounds, area.normalized());
  return sample;
}

// Adds sample's strains in `current` to its region's sums, weighted.
void AddSample(const LayerSamples::Sample& sample, const Ring& ring,
               RegionLayers* sum) {
  const double w = sample.weight;
  std::array<Tangents, kWallLayers> at;
  for (int k = 0; k < kWallLayers; ++k) {
    at[k] = ring.TangentsAt(sample.v, kLayerDepth[k]);
  }
  const Bounds bounds = ThirdBounds(ring, sample.v);
  const double stretch =
      (bounds[kWallLayers] - bounds[0]).norm() / sample.chord;
  sum->err_percent += w * 100.0 * 0.5 * (stretch * stretch - 1.0);
  const Eigen::Vector3d normal = at[1].xu.cross(at[1].xv).normalized();
  const std::array<double, kWallLayers> thickness =
      ThirdThicknesses(bounds, normal);
  for (int k = 0; k < kWallLayers; ++k) {
    const SurfaceStrain strain =
        PlaneStrain(sample.xu[k], sample.xv[k], at[k].xu, at[k].xv,
                    sample.xv[k], sample.xu[k]);
    LayerStrain& layer = sum->layers[k];
    layer.ecc_percent += w * 100.0 * strain.ecc;
    layer.ell_percent += w * 100.0 * strain.ell;
    layer.thickening_percent +=
        w * 100.0 * (thickness[k] / sample.third_thickness[k] - 1.0);
  }
}

void Divide(double weight, RegionLayers* region) {
  const double scale =
      weight > 0.0 ? 1.0 / weight : std::numeric_limits<double>::quiet_NaN();
  region->err_percent *= scale;
  for (LayerStrain& layer : region->layers) {
    for (double* value :
         {&layer.ecc_percent, &layer.ell_percent, &layer.thickening_percent}) {
      *value *= scale;
    }
  }
}

}  // namespace

LayerSamples SampleLayers(const Model& reference, const RegionLayout& layout) {
  LayerSamples out;
  if (!reference.config.Solid()) return out;
  out.num_regions = Regions(layout).size();
  const double s_min = std::sin(reference.config.u_min);
  const double s_max = std::sin(reference.config.u_max);
  out.samples.reserve(kLatitudes * kLongitudes);
  for (int i = 0; i < kLatitudes; ++i) {
    const Ring ring(
        reference, std::asin(s_min + (s_max - s_min) * (i + 0.5) / kLatitudes));
    for (int j = 0; j < kLongitudes; ++j) {
      const double v = -kPi + 2.0 * kPi * (j + 0.5) / kLongitudes;
      out.samples.push_back(ReferenceSample(ring, v, layout));
    }
  }
  return out;
}

std::vector<RegionLayers> SummarizeLayers(const LayerSamples& reference,
                                          const Model& current) {
  if (reference.samples.empty()) return {};
  std::vector<RegionLayers> regions(reference.num_regions);
  std::vector<double> weight(reference.num_regions, 0.0);
  std::optional<Ring> ring;
  for (const LayerSamples::Sample& sample : reference.samples) {
    if (!ring || ring->u != sample.u) ring.emplace(current, sample.u);
    AddSample(sample, *ring, &regions[sample.region]);
    weight[sample.region] += sample.weight;
  }
  for (size_t r = 0; r < regions.size(); ++r) Divide(weight[r], &regions[r]);
  return regions;
}

}  // namespace pfdm
