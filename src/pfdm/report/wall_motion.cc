#include "pfdm/report/wall_motion.h"

#include <array>
#include <cmath>

#include "pfdm/report/material_rings.h"
#include "pfdm/report/surface_strain.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

// Samples per axis of the whole surface: a few hundred per segment.
constexpr int kLatitudeSamples = 60;
constexpr int kLongitudeSamples = 120;

// A row's v, cell centres from -pi.
using RowAngles = std::array<double, kLongitudeSamples>;
const RowAngles& RowV() {
  static const RowAngles v = [] {
    RowAngles out;
    for (int j = 0; j < kLongitudeSamples; ++j) {
      out[j] = -kPi + 2.0 * kPi * (j + 0.5) / kLongitudeSamples;
    }
    return out;
  }();
  return v;
}

// The mid-wall's tangents at a row's samples (SurfaceTangentsAlong).
struct RowTangents {
  RowTangents(const Model& model, const RingFunctions& ring) {
    SurfaceTangentsAlong(model, ring, RowV().data(), kLongitudeSamples, 0.0,
                         xu.data(), xv.data());
  }
  std::array<Eigen::Vector3d, kLongitudeSamples> xu, xv;
};

int SectorsOf(const RegionLayout& layout, RegionLevel level) {
  return level == kBasal  ? layout.basal_sectors
         : level == kMid  ? layout.mid_sectors
         : level == kApex ? 1
                          : layout.apical_sectors;
}

// Where sector 0 of a level begins, in radians past the anchor in the
// layout's sense: at the anchor itself when not anatomical; anatomical,
// basal and mid sector 0 (anterior) ends at the anterior insertion and
// apical sector 1 (septal) is centred on the middle of sectors 1 and 2 of
// the levels above, 60 degrees past it (RegionLayout).
double SectorStart(const RegionLayout& layout, RegionLevel level) {
  const double width = 2.0 * kPi / SectorsOf(layout, level);
  if (!layout.anatomical || level == kApex) return 0.0;
  if (level != kApical) return -width;
  return kPi / 3.0 - 1.5 * width;
}

std::string RegionName(const RegionLayout& layout, RegionLevel level,
                       int sector) {
  static const char* const kLevels[] = {"basal", "mid", "apical"};
  static const char* const kWalls[] = {"anterior",      "anteroseptal",
                                       "inferoseptal",  "inferior",
                                       "inferolateral", "anterolateral"};
  static const char* const kApicalWalls[] = {"anterior", "septal", "inferior",
                                             "lateral"};
  if (level == kApex) return "apex";
  const int sectors = SectorsOf(layout, level);
  const std::string prefix = std::string(kLevels[level]) + " ";
  if (layout.anatomical && level != kApical && sectors == 6) {
    return prefix + kWalls[sector];
  }
  if (layout.anatomical && level == kApical && sectors == 4) {
    return prefix + kApicalWalls[sector];
  }
  return prefix + std::to_string(sector + 1);
}

// Row i's latitude, cells equally spaced in sin u between s_min and s_max.
double RowU(double s_min, double s_max, int i) {
  return std::asin(s_min + (s_max - s_min) * (i + 0.5) / kLatitudeSamples);
}

// Wraps an angle into [-pi, pi).
double Wrapped(double angle) {
  return angle - 2.0 * kPi * std::floor((angle + kPi) / (2.0 * kPi));
}

// Surface area per unit of sin u and v at (u, v) on the model: the
// weight of a sample on a grid equally spaced in sin u and v.
constexpr double kAreaStep = 1e-5;  // AreaWeight's difference step in u, v.

double AreaWeight(const Model& model, double u, double v) {
  constexpr double h = kAreaStep;
  const Eigen::Vector3d xu =
      (model.ModelPoint(u + h, v) - model.ModelPoint(u - h, v)) / (2 * h);
  const Eigen::Vector3d xv =
      (model.ModelPoint(u, v + h) - model.ModelPoint(u, v - h)) / (2 * h);
  return xu.cross(xv).norm() / std::cos(u);
}

}  // namespace

std::vector<WallRegion> Regions(const RegionLayout& layout) {
  std::vector<WallRegion> regions;
  std::vector<RegionLevel> levels{kBasal, kMid, kApical};
  if (layout.apex_cap_fraction > 0.0) levels.push_back(kApex);
  for (RegionLevel level : levels) {
    const int sectors = SectorsOf(layout, level);
    const double width = 2.0 * kPi / sectors;
    for (int s = 0; s < sectors; ++s) {
      WallRegion region;
      region.segment = static_cast<int>(regions.size()) + 1;
      region.level = level;
      region.sector = s;
      const double start = SectorStart(layout, level) + width * s;
      // The sector's longitudes from its first edge in the layout's sense.
      const double first = layout.direction > 0 ? start : -(start + width);
      region.v_begin = level == kApex ? -kPi : Wrapped(layout.anchor_v + first);
      region.v_end = region.v_begin + width;
      region.name = RegionName(layout, level, s);
      regions.push_back(region);
    }
  }
  return regions;
}

namespace {

// Ring u's height on the reference from its apex, a fraction of the apex's
// to the base rim's.
double HeightFraction(const Model& reference, double u) {
  const double apex = RingHeight(reference, reference.config.u_min);
  const double base = RingHeight(reference, reference.config.u_max);
  return (RingHeight(reference, u) - apex) / (base - apex);
}

// The region of longitude v on a ring at height `fraction`.
int RegionAt(double fraction, double v, const RegionLayout& layout) {
  const int cap =
      layout.basal_sectors + layout.mid_sectors + layout.apical_sectors;
  if (fraction < layout.apex_cap_fraction) return cap;
  const RegionLevel level = fraction >= 2.0 / 3.0   ? kBasal
                            : fraction >= 1.0 / 3.0 ? kMid
                                                    : kApical;
  const int sectors = SectorsOf(layout, level);
  const double past =
      layout.direction * (v - layout.anchor_v) - SectorStart(layout, level);
  const double turn = past / (2.0 * kPi);
  const int sector =
      static_cast<int>(std::floor((turn - std::floor(turn)) * sectors)) %
      sectors;
  int first = 0;
  for (RegionLevel before = kBasal; before < level;
       before = static_cast<RegionLevel>(before + 1)) {
    first += SectorsOf(layout, before);
  }
  return first + sector;
}

}  // namespace

int AssignRegion(const Model& reference, double u, double v,
                 const RegionLayout& layout) {
  return RegionAt(HeightFraction(reference, u), v, layout);
}

namespace {

// A solid's endocardial and epicardial rings at the samples' longitudes.
struct WallRings {
  WallRings(const Model& model, double u) : solid(model.config.Solid()) {
    if (!solid) return;
    endo = SampleRing(model, u, kLongitudeSamples, -1.0);
    epi = SampleRing(model, u, kLongitudeSamples, 1.0);
  }
  double Thickness(const Model& model, double u, double v, int j,
                   const Eigen::Vector3d& xu, const Eigen::Vector3d& xv) const {
    return WallThickness(model, u, v, endo.points[j], epi.points[j], xu, xv);
  }
  bool solid;
  MaterialRing endo, epi;
};

// Row i of SampleReference: the samples of latitude u.
void SampleReferenceRow(const Model& reference, const RegionLayout& layout,
                        double u, ReferenceSamples::Sample* row) {
  const MaterialRing before = SampleRing(reference, u, kLongitudeSamples);
  const RingFunctions ring(reference, u);
  const RowTangents tangents(reference, ring);
  const WallRings walls(reference, u);
  const double fraction = HeightFraction(reference, u);
  for (int j = 0; j < kLongitudeSamples; ++j) {
    const double v = RowV()[j];
    ReferenceSamples::Sample& sample = row[j];
    sample.region = RegionAt(fraction, v, layout);
    sample.weight = AreaWeight(reference, u, v);
    sample.from = before.points[j] - before.centroid;
    const Eigen::Vector3d& xu = tangents.xu[j];
    const Eigen::Vector3d& xv = tangents.xv[j];
    sample.plane_inverse = ReferencePlaneInverse(xu, xv, xv, xu);
    if (walls.solid) {
      sample.thickness = walls.Thickness(reference, u, v, j, xu, xv);
    }
  }
}

}  // namespace

ReferenceSamples SampleReference(const Model& reference,
                                 const RegionLayout& layout) {
  ReferenceSamples out;
  out.num_regions = Regions(layout).size();
  // Cell centres equally spaced in sin u and v (equal areas on a sphere),
  // weighted by the reference surface's area; the pole is never sampled.
  out.s_min = std::sin(reference.config.u_min);
  out.s_max = std::sin(reference.config.u_max);
  out.axis = LongAxis(reference);
  out.samples.resize(kLatitudeSamples * kLongitudeSamples);
  for (int i = 0; i < kLatitudeSamples; ++i) {
    SampleReferenceRow(reference, layout, RowU(out.s_min, out.s_max, i),
                       &out.samples[i * kLongitudeSamples]);
  }
  return out;
}

void ResampleReference(const Model& reference, const RegionLayout& layout,
                       double u_low, double u_high, ReferenceSamples* samples) {
  if (u_low <= reference.config.u_min || u_high >= reference.config.u_max) {
    *samples = SampleReference(reference, layout);
    return;
  }
  for (int i = 0; i < kLatitudeSamples; ++i) {
    const double u = RowU(samples->s_min, samples->s_max, i);
    // A row just outside the range still differences into it (AreaWeight).
    if (u < u_low - kAreaStep || u > u_high + kAreaStep) continue;
    SampleReferenceRow(reference, layout, u,
                       &samples->samples[i * kLongitudeSamples]);
  }
}

namespace {

void SampleRow(const Model& current, double u, CurrentSamples::Sample* row) {
  const MaterialRing after = SampleRing(current, u, kLongitudeSamples);
  const RingFunctions ring(current, u);
  const RowTangents tangents(current, ring);
  const WallRings walls(current, u);
  for (int j = 0; j < kLongitudeSamples; ++j) {
    const double v = RowV()[j];
    CurrentSamples::Sample& sample = row[j];
    sample.to = after.points[j] - after.centroid;
    sample.xu = tangents.xu[j];
    sample.xv = tangents.xv[j];
    if (walls.solid) {
      sample.thickness =
          walls.Thickness(current, u, v, j, sample.xu, sample.xv);
    }
  }
}

}  // namespace

CurrentSamples SampleCurrent(const ReferenceSamples& reference,
                             const Model& current) {
  CurrentSamples out;
  out.solid = current.config.Solid();
  out.samples.resize(kLatitudeSamples * kLongitudeSamples);
  for (int i = 0; i < kLatitudeSamples; ++i) {
    out.row_u.push_back(RowU(reference.s_min, reference.s_max, i));
    SampleRow(current, out.row_u[i], &out.samples[i * kLongitudeSamples]);
  }
  return out;
}

void ResampleRows(const Model& current, double u_low, double u_high,
                  CurrentSamples* samples) {
  for (size_t i = 0; i < samples->row_u.size(); ++i) {
    const double u = samples->row_u[i];
    if (u < u_low || u > u_high) continue;
    SampleRow(current, u, &samples->samples[i * kLongitudeSamples]);
  }
}

namespace {

using RowSums = RegionComparison::RowSums;

// Row i's samples summed per region, weighted by their areas.
void SumRow(const ReferenceSamples& reference, const CurrentSamples& current,
            int i, RowSums* sums) {
  sums->assign(reference.num_regions, RegionComparison::RegionSum());
  const size_t first = static_cast<size_t>(i) * kLongitudeSamples;
  for (size_t k = first; k < first + kLongitudeSamples; ++k) {
    const ReferenceSamples::Sample& sample = reference.samples[k];
    const CurrentSamples::Sample& now = current.samples[k];
    RegionComparison::RegionSum& region = (*sums)[sample.region];
    RegionMotion& motion = region.sum;
    const double w = sample.weight;
    const Eigen::Vector3d& from = sample.from;
    const Eigen::Vector3d& to = now.to;
    motion.rotation_deg +=
        w * AngleAbout(from, to, reference.axis) * kDegreesPerRadian;
    motion.radial_contraction_percent +=
        w * 100.0 * (1.0 - to.norm() / from.norm());
    const SurfaceStrain strain =
        PlaneStrain(sample.plane_inverse, now.xu, now.xv);
    motion.ecc_percent += w * 100.0 * strain.ecc;
    motion.ell_percent += w * 100.0 * strain.ell;
    motion.ecl_percent += w * 100.0 * strain.ecl;
    if (current.solid) {
      motion.thickening_percent +=
          w * 100.0 * (now.thickness / sample.thickness - 1.0);
    }
    region.weight += w;
  }
}

// The regions' means over all rows, the rows' sums added in row order.
std::vector<RegionMotion> RegionMeans(const ReferenceSamples& reference,
                                      const std::vector<const RowSums*>& rows) {
  const size_t count = reference.num_regions;
  std::vector<RegionMotion> motion(count);
  std::vector<double> weight(count, 0.0);
  for (const RowSums* row : rows) {
    for (size_t r = 0; r < count; ++r) {
      const RegionComparison::RegionSum& sum = (*row)[r];
      if (sum.weight == 0.0) continue;
      motion[r].rotation_deg += sum.sum.rotation_deg;
      motion[r].radial_contraction_percent +=
          sum.sum.radial_contraction_percent;
      motion[r].ecc_percent += sum.sum.ecc_percent;
      motion[r].ell_percent += sum.sum.ell_percent;
      motion[r].ecl_percent += sum.sum.ecl_percent;
      motion[r].thickening_percent += sum.sum.thickening_percent;
      weight[r] += sum.weight;
    }
  }
  const double s_min = reference.s_min, s_max = reference.s_max;
  for (size_t r = 0; r < count; ++r) {
    if (weight[r] == 0.0) continue;
    motion[r].rotation_deg /= weight[r];
    motion[r].radial_contraction_percent /= weight[r];
    motion[r].ecc_percent /= weight[r];
    motion[r].ell_percent /= weight[r];
    motion[r].ecl_percent /= weight[r];
    motion[r].thickening_percent /= weight[r];
    // Each sample stands for a cell of (s_max - s_min) / kLatitudeSamples
    // in sin u and 2 pi / kLongitudeSamples in v.
    motion[r].area_mm2 = weight[r] * (s_max - s_min) / kLatitudeSamples * 2.0 *
                         kPi / kLongitudeSamples;
  }
  return motion;
}

}  // namespace

RegionComparison::RegionComparison(const ReferenceSamples& reference,
                                   const CurrentSamples& current)
    : rows_(kLatitudeSamples) {
  std::vector<const RowSums*> rows;
  for (int i = 0; i < kLatitudeSamples; ++i) {
    SumRow(reference, current, i, &rows_[i]);
    rows.push_back(&rows_[i]);
  }
  motion_ = RegionMeans(reference, rows);
}

std::vector<RegionMotion> RegionComparison::Recompared(
    const ReferenceSamples& reference, const CurrentSamples& current,
    double u_low, double u_high) const {
  std::vector<RowSums> fresh(kLatitudeSamples);
  std::vector<const RowSums*> rows;
  for (int i = 0; i < kLatitudeSamples; ++i) {
    const double u = current.row_u[i];
    // ResampleReference's margin: a row just outside its range differences
    // into it (AreaWeight).
    const bool moved = u >= u_low - kAreaStep && u <= u_high + kAreaStep;
    if (moved) SumRow(reference, current, i, &fresh[i]);
    rows.push_back(moved ? &fresh[i] : &rows_[i]);
  }
  return RegionMeans(reference, rows);
}

std::vector<RegionMotion> CompareRegions(const ReferenceSamples& reference,
                                         const CurrentSamples& current) {
  return RegionComparison(reference, current).motion();
}

std::vector<RegionMotion> SummarizeRegions(const ReferenceSamples& reference,
                                           const Model& current) {
  return CompareRegions(reference, SampleCurrent(reference, current));
}

std::vector<RegionMotion> SummarizeRegions(const Model& reference,
                                           const Model& current,
                                           const RegionLayout& layout) {
  return SummarizeRegions(SampleReference(reference, layout), current);
}

}  // namespace pfdm
