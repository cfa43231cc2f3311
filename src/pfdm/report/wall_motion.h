// Regional wall motion: rotation and radial contraction per AHA-style
// segment.
#ifndef PFDM_REPORT_WALL_MOTION_H_
#define PFDM_REPORT_WALL_MOTION_H_

#include <string>
#include <vector>

#include "Eigen/Core"
#include "pfdm/model/model.h"

namespace pfdm {

// Levels are thirds of the reference (frame 0) model's axis from apex to
// base rim; each level is cut into equal sectors of longitude v, counted
// counter-clockwise about +z (seen from the base) from v = -pi.  The AHA
// layout has 6 basal, 6 mid and 4 apical segments, numbered 1-6 basal,
// 7-12 mid, 13-16 apical; it anchors sector 1 at the anterior RV insertion,
// which point data do not show, so here sector 1 starts at the model's -x.
struct RegionLayout {
  int basal_sectors = 6;
  int mid_sectors = 6;
  int apical_sectors = 4;
};

enum RegionLevel : int { kBasal = 0, kMid = 1, kApical = 2 };

struct WallRegion {
  int segment = 0;  // 1-based, basal first.
  RegionLevel level = kBasal;
  int sector = 0;  // 0-based within the level.
  double v_begin = 0.0;
  double v_end = 0.0;
  std::string Name() const;  // e.g. "basal 2".
};

std::vector<WallRegion> Regions(const RegionLayout& layout);

// Index into Regions(layout) of the material point (u, v), by the axial
// position of its ring on the reference model.
int AssignRegion(const Model& reference, double u, double v,
                 const RegionLayout& layout);

// Measured on material points in world coordinates (material_rings.h).
struct RegionMotion {
  // Mean turn of the region's material points about frame 0's long axis
  // (about their ring's centroid), degrees, right-handed apex to base.
  double rotation_deg = 0.0;
  // Mean of 1 - rho / rho0, percent, rho a material point's distance from
  // its ring's centroid.
  double radial_contraction_percent = 0.0;
  // Mean Green-Lagrange strains of the region's fitted surface, percent
  // (report/surface_strain.h): circumferential, longitudinal and their
  // shear.  Negative Ecc and Ell are shortening.
  double ecc_percent = 0.0;
  double ell_percent = 0.0;
  double ecl_percent = 0.0;
  // A solid's wall thickening: mean of 100 (T / T0 - 1), T the wall
  // thickness at the material point (material_rings.h WallThickness); 0
  // for a single surface.
  double thickening_percent = 0.0;
  // The region's area on the reference (frame 0) surface, mm^2: the weight
  // of its means in a global one.
  double area_mm2 = 0.0;
};

// One entry per region of Regions(layout), each an area-weighted mean over
// samples of the region (equal steps in sin u and v).
std::vector<RegionMotion> SummarizeRegions(const Model& reference,
                                           const Model& current,
                                           const RegionLayout& layout);

// What SummarizeRegions takes from the reference model at its samples
// (region, area weight, ring, tangents): the same for every frame of a fit,
// so a fit's frames share one (AnalyzeFit) and give the same numbers.
struct ReferenceSamples {
  struct Sample {
    int region = 0;
    double weight = 0.0;
    Eigen::Vector3d from =
        Eigen::Vector3d::Zero();  // From its ring's centroid.
    Eigen::Vector3d xu = Eigen::Vector3d::Zero(), xv = Eigen::Vector3d::Zero();
    double thickness = 0.0;  // A solid's WallThickness; 0 otherwise.
  };
  size_t num_regions = 0;
  double s_min = 0.0, s_max = 0.0;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  std::vector<Sample> samples;  // Latitude by latitude.
};
ReferenceSamples SampleReference(const Model& reference,
                                 const RegionLayout& layout);
std::vector<RegionMotion> SummarizeRegions(const ReferenceSamples& reference,
                                           const Model& current);

}  // namespace pfdm

#endif  // PFDM_REPORT_WALL_MOTION_H_
