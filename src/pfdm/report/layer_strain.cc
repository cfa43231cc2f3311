#include "pfdm/report/layer_strain.h"

#include <cmath>
#include <limits>

#include "Eigen/Dense"
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
constexpr double kDepthW[LayerSamples::kDepths] = {-1.0, -0.5, 0.0, 0.5, 1.0};
// Simpson's rule for the mean over [-1, 1] on those depths.
constexpr double kSimpson[LayerSamples::kDepths] = {
    1.0 / 12, 4.0 / 12, 2.0 / 12, 4.0 / 12, 1.0 / 12};
constexpr int kLayerOfDepth[kWallLayers] = {0, 2, 4};  // kLayerDepth's.
constexpr double kThirdBounds[kWallLayers + 1] = {-1.0, -1.0 / 3, 1.0 / 3, 1.0};

struct Tangents {
  Eigen::Vector3d xu, xv, xw;
};

Tangents TangentsAt(const Model& model, double u, double v, double w) {
  const double scale = 0.5 / kStep;
  return {
      (model.WorldPoint(u + kStep, v, w) - model.WorldPoint(u - kStep, v, w)) *
          scale,
      (model.WorldPoint(u, v + kStep, w) - model.WorldPoint(u, v - kStep, w)) *
          scale,
      (model.WorldPoint(u, v, w + kStep) - model.WorldPoint(u, v, w - kStep)) *
          scale};
}

// Each third's thickness along `normal` (unit).
std::array<double, kWallLayers> ThirdThicknesses(
    const Model& model, double u, double v, const Eigen::Vector3d& normal) {
  std::array<Eigen::Vector3d, kWallLayers + 1> bounds;
  for (int k = 0; k <= kWallLayers; ++k) {
    bounds[k] = model.WorldPoint(u, v, kThirdBounds[k]);
  }
  std::array<double, kWallLayers> thickness;
  for (int k = 0; k < kWallLayers; ++k) {
    thickness[k] = std::abs((bounds[k + 1] - bounds[k]).dot(normal));
  }
  return thickness;
}

// The reference's share of sample (u, v): region, area weight (per unit of
// sin u and v, the mid-wall's), tangents, normal coefficients, thirds.
LayerSamples::Sample ReferenceSample(const Model& reference, double u, double v,
                                     const RegionLayout& layout) {
  LayerSamples::Sample sample;
  sample.u = u;
  sample.v = v;
  sample.region = AssignRegion(reference, u, v, layout);
  std::array<Tangents, LayerSamples::kDepths> at;
  for (int d = 0; d < LayerSamples::kDepths; ++d) {
    at[d] = TangentsAt(reference, u, v, kDepthW[d]);
    Eigen::Matrix3d basis;
    basis << at[d].xu, at[d].xv, at[d].xw;
    const Eigen::Vector3d normal = at[d].xu.cross(at[d].xv).normalized();
    sample.normal_coefficients[d] = basis.partialPivLu().solve(normal);
  }
  for (int k = 0; k < kWallLayers; ++k) {
    sample.xu[k] = at[kLayerOfDepth[k]].xu;
    sample.xv[k] = at[kLayerOfDepth[k]].xv;
  }
  const Tangents& mid = at[2];
  const Eigen::Vector3d area = mid.xu.cross(mid.xv);
  sample.weight = area.norm() / std::cos(u);
  sample.third_thickness = ThirdThicknesses(reference, u, v, area.normalized());
  return sample;
}

// Adds sample's strains in `current` to its region's sums, weighted.
void AddSample(const LayerSamples::Sample& sample, const Model& current,
               RegionLayers* sum) {
  const double w = sample.weight;
  std::array<Tangents, LayerSamples::kDepths> at;
  for (int d = 0; d < LayerSamples::kDepths; ++d) {
    at[d] = TangentsAt(current, sample.u, sample.v, kDepthW[d]);
    const Eigen::Vector3d& c = sample.normal_coefficients[d];
    const Eigen::Vector3d fn =
        c[0] * at[d].xu + c[1] * at[d].xv + c[2] * at[d].xw;
    const double err = 100.0 * 0.5 * (fn.squaredNorm() - 1.0);
    sum->err_percent += w * kSimpson[d] * err;
    for (int k = 0; k < kWallLayers; ++k) {
      if (kLayerOfDepth[k] == d) sum->layers[k].err_percent += w * err;
    }
  }
  const Eigen::Vector3d normal = at[2].xu.cross(at[2].xv).normalized();
  const std::array<double, kWallLayers> thickness =
      ThirdThicknesses(current, sample.u, sample.v, normal);
  for (int k = 0; k < kWallLayers; ++k) {
    const Tangents& t = at[kLayerOfDepth[k]];
    const SurfaceStrain strain = PlaneStrain(sample.xu[k], sample.xv[k], t.xu,
                                             t.xv, sample.xv[k], sample.xu[k]);
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
    for (double* value : {&layer.ecc_percent, &layer.ell_percent,
                          &layer.err_percent, &layer.thickening_percent}) {
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
    const double u =
        std::asin(s_min + (s_max - s_min) * (i + 0.5) / kLatitudes);
    for (int j = 0; j < kLongitudes; ++j) {
      const double v = -kPi + 2.0 * kPi * (j + 0.5) / kLongitudes;
      out.samples.push_back(ReferenceSample(reference, u, v, layout));
    }
  }
  return out;
}

std::vector<RegionLayers> SummarizeLayers(const LayerSamples& reference,
                                          const Model& current) {
  if (reference.samples.empty()) return {};
  std::vector<RegionLayers> regions(reference.num_regions);
  std::vector<double> weight(reference.num_regions, 0.0);
  for (const LayerSamples::Sample& sample : reference.samples) {
    AddSample(sample, current, &regions[sample.region]);
    weight[sample.region] += sample.weight;
  }
  for (size_t r = 0; r < regions.size(); ++r) Divide(weight[r], &regions[r]);
  return regions;
}

}  // namespace pfdm
