// Strain per layer of a solid's wall (issue 32): each segment's Ecc and Ell
// at the endocardium, the mid-wall and the epicardium, each third of the
// wall's thickening, and the radial strain Err across the wall, measured
// on the fitted model's material points (u, v, w) against the reference
// frame's.  A mid-wall fit has no wall: it has no layers (an empty
// vector), never zeros.
#ifndef PFDM_REPORT_LAYER_STRAIN_H_
#define PFDM_REPORT_LAYER_STRAIN_H_

#include <array>
#include <vector>

#include "Eigen/Core"
#include "pfdm/model/model.h"
#include "pfdm/report/wall_motion.h"

namespace pfdm {

// The three layers, inside out; their w (model/transmural.h) and names.
inline constexpr int kWallLayers = 3;
inline constexpr double kLayerDepth[kWallLayers] = {-1.0, 0.0, 1.0};
inline constexpr const char* kLayerNames[kWallLayers] = {
    "endocardium", "midwall", "epicardium"};

// One layer of one segment, percent, area-weighted over the segment.
struct LayerStrain {
  // Green-Lagrange strains on the layer's surface w in its own tangent
  // plane, as surface_strain.h measures the mid-wall's: e_c along X_v, e_l
  // perpendicular to it in the plane (apex to base).
  double ecc_percent = 0.0;
  double ell_percent = 0.0;
  // The layer's third of the wall (w in [-1, -1/3], [-1/3, 1/3], [1/3,
  // 1]): 100 (T / T0 - 1), T the third's thickness along the mid-wall's
  // current normal at (u, v), as material_rings.h's WallThickness reads the
  // whole wall.
  double thickening_percent = 0.0;
};

struct RegionLayers {
  std::array<LayerStrain, kWallLayers> layers;  // kLayerDepth's order.
  // Err across the wall: the Green-Lagrange strain (|x| / |X|)^2 - 1) / 2 of
  // the transmural material line's chord, (u, v, -1) to (u, v, +1): its
  // stretch, with any shear across the wall (a transmural twist) in it, as
  // tags through the wall measure it.  Not the strain at a point across the
  // wall: the fibre's local stretch at a wall is the slope of the fitted
  // depth profile there, which the tags do not fix (on the LV phantom it
  // read 85 points off at the endocardium, 168 at the epicardium).
  double err_percent = 0.0;
};

// What the measure takes from the reference model at its samples (region,
// area weight, tangents, thicknesses), shared by a fit's frames.
struct LayerSamples {
  struct Sample {
    double u = 0.0, v = 0.0;
    int region = 0;
    double weight = 0.0;
    // At kLayerDepth: the reference tangents X_u, X_v.
    std::array<Eigen::Vector3d, kWallLayers> xu, xv;
    double chord = 0.0;  // |X(u, v, 1) - X(u, v, -1)|, mm.
    std::array<double, kWallLayers> third_thickness{};  // T0, mm.
  };
  size_t num_regions = 0;
  std::vector<Sample> samples;
};

// Empty samples for a model without a wall (not Solid()).
LayerSamples SampleLayers(const Model& reference, const RegionLayout& layout);

// One entry per region of the layout; empty when the samples are (no wall).
std::vector<RegionLayers> SummarizeLayers(const LayerSamples& reference,
                                          const Model& current);

}  // namespace pfdm

#endif  // PFDM_REPORT_LAYER_STRAIN_H_
