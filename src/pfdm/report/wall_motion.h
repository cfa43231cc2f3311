// Regional wall motion: rotation and radial contraction per AHA-style
// segment.
#ifndef PFDM_REPORT_WALL_MOTION_H_
#define PFDM_REPORT_WALL_MOTION_H_

#include <limits>
#include <string>
#include <vector>

#include "Eigen/Core"
#include "pfdm/model/model.h"

namespace pfdm {

// Levels are thirds of the reference (frame 0) model's axis from apex to
// base rim, the apical one less the apex cap (segment 17: the surface within
// apex_cap_fraction of the axis of the apex pole); each level is cut into
// equal sectors of longitude v.  The AHA 17-segment model (Cerqueira et al.
// 2002) has 6 basal, 6 mid and 4 apical segments and the cap, numbered 1-6
// basal, 7-12 mid, 13-16 apical, 17 the apex.
//
// Anatomical (an RV insertion known, rv_insertion.h): sectors run from the
// anterior RV insertion at v = anchor_v in the sense `direction` (-1:
// decreasing v, clockwise seen from the base, as anterior -> septum ->
// inferior runs in a right-handed frame); basal and mid sector 1 (anterior)
// ends at the insertion, sectors 2 and 3 (anteroseptal, inferoseptal) lie
// past it, 60 degrees each; the apical septal sector (2 of 4) is centred on
// the middle of those two, 60 degrees past the insertion.  Otherwise sector 1
// of every level starts at v = -pi (the model's -x, which the start takes
// from the data) and sectors run counter-clockwise seen from the base: the
// numbers then depend on the case, not the anatomy.
struct RegionLayout {
  int basal_sectors = 6;
  int mid_sectors = 6;
  int apical_sectors = 4;
  // Segment 17's reach from the apex pole, a fraction of the apex-to-base
  // length; 0: no cap (16 segments, the apical third whole).  A tenth makes
  // the cap about as large as a segment (on the LV phantom 1.05 times the
  // mean's area).
  double apex_cap_fraction = 0.1;
  bool anatomical = false;
  double anchor_v = -3.14159265358979323846;  // Radians.
  double direction = 1.0;                     // +1 or -1.
  // Anatomical: where the insertion came from ("RV_INSERT points",
  // "--rv_insertion"); otherwise why the segments are not anatomical.
  std::string anchor = "no RV insertion given";
  // Anatomical: the inferior insertion's v (radians; NaN when unknown) and
  // how many points gave each insertion.
  double inferior_v = std::numeric_limits<double>::quiet_NaN();
  int anterior_points = 0, inferior_points = 0;
};

enum RegionLevel : int { kBasal = 0, kMid = 1, kApical = 2, kApex = 3 };

struct WallRegion {
  int segment = 0;  // 1-based, basal first; the apex cap last (17).
  RegionLevel level = kBasal;
  int sector = 0;  // 0-based within the level, in the layout's sense.
  // The sector's longitudes: [v_begin, v_end), v_begin in [-pi, pi), v_end
  // up to 2 pi past it (the cap: -pi to pi).
  double v_begin = 0.0;
  double v_end = 0.0;
  // The AHA name ("basal anterior", "mid inferoseptal", "apical septal",
  // "apex") in an anatomical 6/6/4 layout; otherwise "basal 2" (and "apex").
  std::string name;
  const std::string& Name() const { return name; }
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
    // The tangent plane's G^-1 (ReferencePlaneInverse of X_u, X_v, e_c
    // along X_v), which every frame's strain there takes.
    Eigen::Matrix2d plane_inverse = Eigen::Matrix2d::Identity();
    double thickness = 0.0;  // A solid's WallThickness; 0 otherwise.
  };
  size_t num_regions = 0;
  double s_min = 0.0, s_max = 0.0;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  std::vector<Sample> samples;  // Latitude by latitude.
};
ReferenceSamples SampleReference(const Model& reference,
                                 const RegionLayout& layout);
// Samples taken on a model that `reference` differs from only for u in
// [u_low, u_high] (a step of one knot of end-diastole's, for the delta
// method, number_uncertainty.h), made SampleReference(reference, layout):
// the rows in the range taken again, or every row when the range reaches
// the apex or the base rim, whose heights cut the levels.
void ResampleReference(const Model& reference, const RegionLayout& layout,
                       double u_low, double u_high, ReferenceSamples* samples);
std::vector<RegionMotion> SummarizeRegions(const ReferenceSamples& reference,
                                           const Model& current);

// SummarizeRegions in two steps, what the current model gives at the
// samples' material points and its comparison with the reference's, so
// that the delta method (number_uncertainty.h) re-measures only the rows a
// step moves: a knot's step moves the model only between its neighbours.
struct CurrentSamples {
  struct Sample {
    Eigen::Vector3d to = Eigen::Vector3d::Zero();  // From its ring's centroid.
    Eigen::Vector3d xu = Eigen::Vector3d::Zero(), xv = Eigen::Vector3d::Zero();
    double thickness = 0.0;  // A solid's WallThickness; 0 otherwise.
  };
  bool solid = false;
  std::vector<double> row_u;    // The latitudes' u.
  std::vector<Sample> samples;  // Latitude by latitude, as the reference's.
};
CurrentSamples SampleCurrent(const ReferenceSamples& reference,
                             const Model& current);
// Re-measures on `current` the rows whose u lies in [u_low, u_high].
void ResampleRows(const Model& current, double u_low, double u_high,
                  CurrentSamples* samples);
std::vector<RegionMotion> CompareRegions(const ReferenceSamples& reference,
                                         const CurrentSamples& current);

// CompareRegions kept row by row, so that a step that moves some rows
// (ResampleRows, ResampleReference) compares only those again: the
// comparison of every sample had been a third of the delta method's time.
// The rows' sums are added in row order whether kept or new, so a
// comparison made again gives the same bits as one made from scratch.
class RegionComparison {
 public:
  RegionComparison(const ReferenceSamples& reference,
                   const CurrentSamples& current);
  const std::vector<RegionMotion>& motion() const { return motion_; }
  // CompareRegions(reference, current) of samples that differ from this
  // comparison's only in rows whose u lies in [u_low, u_high] or within
  // ResampleReference's margin of it.
  std::vector<RegionMotion> Recompared(const ReferenceSamples& reference,
                                       const CurrentSamples& current,
                                       double u_low, double u_high) const;

  // A region's weighted sums over one row's samples, and their weights'.
  struct RegionSum {
    RegionMotion sum;
    double weight = 0.0;
  };
  using RowSums = std::vector<RegionSum>;  // One per region.

 private:
  std::vector<RowSums> rows_;
  std::vector<RegionMotion> motion_;
};

}  // namespace pfdm

#endif  // PFDM_REPORT_WALL_MOTION_H_
