#include "pfdm/report/layer_strain.h"

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "pfdm/model/world_points.h"
#include "pfdm/report/surface_strain.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

// A few dozen samples per segment in each layer: equal steps in sin u and
// v, the pole never sampled (as wall_motion's samples).
constexpr int kLatitudes = 36;
constexpr int kLongitudes = 72;
constexpr double kThirdBounds[kWallLayers + 1] = {-1.0, -1.0 / 3, 1.0 / 3, 1.0};

struct Tangents {
  Eigen::Vector3d xu, xv;
};

// The thirds' bounds across the wall at (u, v), endocardium first.
using Bounds = std::array<Eigen::Vector3d, kWallLayers + 1>;

// What a sample needs of a model: each layer's tangents and the thirds'
// bounds.
struct SampleGeometry {
  std::array<Tangents, kWallLayers> tangents;
  Bounds bounds;
};

// The geometry of the samples at longitudes `v` of the ring at u: each
// layer's tangents in closed form (SurfaceTangents on surface w, the
// ring's functions once; on a knot, where X_u has two sides, the mean of
// the two spans' slopes, and the rings 4, 13, 22 and 31 of kLatitudes lie
// on knots), the thirds' bounds in one batch through WorldPoints.
std::vector<SampleGeometry> RingGeometry(const Model& model, double u,
                                         const std::vector<double>& v) {
  std::vector<std::array<double, 3>> at;
  for (double at_v : v) {
    for (double w : kThirdBounds) at.push_back({u, at_v, w});
  }
  std::vector<Eigen::Vector3d> bounds(at.size());
  if (!at.empty()) {
    WorldPoints(model, at.size(), &at[0][0], &at[0][1], &at[0][2], 3,
                bounds.data());
  }
  const RingFunctions ring(model, u);
  std::vector<SampleGeometry> geometry(v.size());
  for (size_t j = 0; j < v.size(); ++j) {
    for (int k = 0; k < kWallLayers; ++k) {
      Tangents& tangents = geometry[j].tangents[k];
      SurfaceTangents(model, ring, v[j], kLayerDepth[k], &tangents.xu,
                      &tangents.xv);
    }
    for (int b = 0; b <= kWallLayers; ++b) {
      geometry[j].bounds[b] = bounds[(kWallLayers + 1) * j + b];
    }
  }
  return geometry;
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
LayerSamples::Sample ReferenceSample(const Model& reference, double u, double v,
                                     const SampleGeometry& geometry,
                                     const RegionLayout& layout) {
  LayerSamples::Sample sample;
  sample.u = u;
  sample.v = v;
  sample.region = AssignRegion(reference, u, v, layout);
  for (int k = 0; k < kWallLayers; ++k) {
    sample.xu[k] = geometry.tangents[k].xu;
    sample.xv[k] = geometry.tangents[k].xv;
  }
  const Eigen::Vector3d area = sample.xu[1].cross(sample.xv[1]);
  sample.weight = area.norm() / std::cos(u);
  const Bounds& bounds = geometry.bounds;
  sample.chord = (bounds[kWallLayers] - bounds[0]).norm();
  sample.third_thickness = ThirdThicknesses(bounds, area.normalized());
  return sample;
}

// Adds sample's strains in `current` to its region's sums, weighted.
void AddSample(const LayerSamples::Sample& sample,
               const SampleGeometry& geometry, RegionLayers* sum) {
  const double w = sample.weight;
  const std::array<Tangents, kWallLayers>& at = geometry.tangents;
  const Bounds& bounds = geometry.bounds;
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
  std::vector<double> v(kLongitudes);
  for (int j = 0; j < kLongitudes; ++j) {
    v[j] = -kPi + 2.0 * kPi * (j + 0.5) / kLongitudes;
  }
  for (int i = 0; i < kLatitudes; ++i) {
    const double u =
        std::asin(s_min + (s_max - s_min) * (i + 0.5) / kLatitudes);
    const std::vector<SampleGeometry> geometry = RingGeometry(reference, u, v);
    for (int j = 0; j < kLongitudes; ++j) {
      out.samples.push_back(
          ReferenceSample(reference, u, v[j], geometry[j], layout));
    }
  }
  return out;
}

std::vector<RegionLayers> SummarizeLayers(const LayerSamples& reference,
                                          const Model& current) {
  if (reference.samples.empty()) return {};
  std::vector<RegionLayers> regions(reference.num_regions);
  std::vector<double> weight(reference.num_regions, 0.0);
  const std::vector<LayerSamples::Sample>& samples = reference.samples;
  // Ring by ring: the samples come in rings of equal u.
  for (size_t first = 0; first < samples.size();) {
    size_t end = first;
    std::vector<double> v;
    while (end < samples.size() && samples[end].u == samples[first].u) {
      v.push_back(samples[end++].v);
    }
    const std::vector<SampleGeometry> geometry =
        RingGeometry(current, samples[first].u, v);
    for (size_t j = first; j < end; ++j) {
      AddSample(samples[j], geometry[j - first], &regions[samples[j].region]);
      weight[samples[j].region] += samples[j].weight;
    }
    first = end;
  }
  for (size_t r = 0; r < regions.size(); ++r) Divide(weight[r], &regions[r]);
  return regions;
}

}  // namespace pfdm
