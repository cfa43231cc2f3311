#include "pfdm/report/frame_numbers.h"

#include <limits>

namespace pfdm {
namespace {

// The surfaces whose volumes a frame reports: the cavity's (a solid's
// endocardium, w = -1, or the mid-wall) and a solid's epicardium.
std::vector<double> VolumeSurfaces(const Model& model) {
  if (model.config.Solid()) return {-1.0, 1.0};
  return {0.0};
}

// The volumes of the cavity's surface and a solid's epicardium (ml), as
// SummarizeFrame's with flat lids or AnalyzeFit's with base planes.
void SetVolumes(const std::vector<double>& ml, ClinicalSummary* c) {
  c->volume_ml = ml[0];
  if (ml.size() > 1) {
    c->myocardial_volume_ml = ml[1] - c->volume_ml;
    c->lv_mass_g = kMyocardialDensity * c->myocardial_volume_ml;
  }
}

// Past every row: a range of rows that holds none.
constexpr double kNoRow = std::numeric_limits<double>::infinity();

// The rows of u that samples resampled for `range` differ in.
MovedU ReferenceRows(const MovedU& range) {
  return range.heights ? MovedU() : range;
}

}  // namespace

FrameMeasurer::FrameMeasurer(const Model& ed, const ReferenceSamples& samples,
                             const std::vector<WallRegion>& regions,
                             const Model& current, const BasePlane* plane)
    : ed_(ed),
      samples_(samples),
      regions_(regions),
      plane_(plane),
      current_(current),
      current_samples_(SampleCurrent(samples, current)),
      comparison_(samples, current_samples_),
      ed_rings_(ed) {
  std::vector<double> ml;
  for (double w : VolumeSurfaces(current)) {
    surfaces_.push_back(CavitySurface(current, plane, w));
    volumes_.emplace_back(current, surfaces_.back(), plane);
    ml.push_back(volumes_.back().ml());
  }
  numbers_.clinical = SummarizeFrame(0, ed_rings_, current, RingSpan(),
                                     /*flat_lid_volumes=*/false);
  SetVolumes(ml, &numbers_.clinical);
  numbers_.regions = comparison_.motion();
  numbers_.strain = SummarizeStrain(regions, numbers_.regions);
}

FrameNumbers FrameMeasurer::Moved(const Model& moved,
                                  const MovedU& range) const {
  // A shift alone moves no sample relative to its ring.
  const bool shifted =
      range.rigid && moved.state.quaternion == current_.state.quaternion;
  MovedU rows = range;
  if (shifted) rows.low = rows.high = kNoRow;
  return Moved(moved, range, ed_rings_, samples_, rows);
}

FrameNumbers FrameMeasurer::Moved(const Model& moved, const MovedU& range,
                                  ReferenceRings& ed_rings,
                                  const ReferenceSamples& samples) const {
  return Moved(moved, range, ed_rings, samples, ReferenceRows(range));
}

FrameNumbers FrameMeasurer::Moved(const Model& moved, const MovedU& range,
                                  ReferenceRings& ed_rings,
                                  const ReferenceSamples& samples,
                                  const MovedU& rows) const {
  if (moved_samples_.samples.empty()) {  // The first step.
    moved_samples_ = current_samples_;
    moved_surfaces_ = surfaces_;
  }
  FrameNumbers numbers;
  numbers.clinical = SummarizeFrame(0, ed_rings, moved, RingSpan(),
                                    /*flat_lid_volumes=*/false);
  std::vector<VertexRange> changed(moved_surfaces_.size());
  if (range.rigid) {
    MoveRigidly(moved);
    for (size_t i = 0; i < changed.size(); ++i) {
      changed[i].last = moved_surfaces_[i].mesh.points.size();
    }
  } else {
    const std::vector<double> ws = VolumeSurfaces(moved);
    for (size_t i = 0; i < moved_surfaces_.size(); ++i) {
      changed[i] = ReplaceVertices(moved, range.low, range.high, ws[i],
                                   &moved_surfaces_[i]);
    }
    ResampleRows(moved, range.low, range.high, &moved_samples_);
  }
  std::vector<double> ml;
  for (size_t i = 0; i < volumes_.size(); ++i) {
    ml.push_back(volumes_[i].MovedMl(moved, moved_surfaces_[i], changed[i]));
  }
  SetVolumes(ml, &numbers.clinical);
  numbers.regions =
      comparison_.Recompared(samples, moved_samples_, rows.low, rows.high);
  numbers.strain = SummarizeStrain(regions_, numbers.regions);
  // Back to current's (same sizes: no allocation).
  for (size_t i = 0; i < moved_surfaces_.size(); ++i) {
    moved_surfaces_[i].mesh.points = surfaces_[i].mesh.points;
  }
  moved_samples_.samples = current_samples_.samples;
  return numbers;
}

void FrameMeasurer::MoveRigidly(const Model& moved) const {
  const Eigen::Matrix3d turn =
      moved.Rotation() * current_.Rotation().transpose();
  const Eigen::Vector3d from(current_.state.center.data());
  const Eigen::Vector3d to(moved.state.center.data());
  for (size_t i = 0; i < moved_surfaces_.size(); ++i) {
    const std::vector<Eigen::Vector3d>& kept = surfaces_[i].mesh.points;
    std::vector<Eigen::Vector3d>& points = moved_surfaces_[i].mesh.points;
    for (size_t k = 0; k < kept.size(); ++k) {
      points[k] = to + turn * (kept[k] - from);
    }
  }
  if (moved.state.quaternion == current_.state.quaternion) return;
  for (CurrentSamples::Sample& sample : moved_samples_.samples) {
    sample.to = turn * sample.to;
    sample.xu = turn * sample.xu;
    sample.xv = turn * sample.xv;
  }
}

FrameNumbers FrameMeasurer::Against(ReferenceRings& ed_rings,
                                    const ReferenceSamples& samples,
                                    const MovedU& range) const {
  const MovedU rows = ReferenceRows(range);
  FrameNumbers numbers;
  numbers.clinical = SummarizeFrame(0, ed_rings, current_, RingSpan(),
                                    /*flat_lid_volumes=*/false);
  const ClinicalSummary& kept = numbers_.clinical;
  numbers.clinical.volume_ml = kept.volume_ml;
  numbers.clinical.myocardial_volume_ml = kept.myocardial_volume_ml;
  numbers.clinical.lv_mass_g = kept.lv_mass_g;
  numbers.regions =
      comparison_.Recompared(samples, current_samples_, rows.low, rows.high);
  numbers.strain = SummarizeStrain(regions_, numbers.regions);
  return numbers;
}

FrameNumbers MeasureFrame(const Model& ed, const ReferenceSamples& samples,
                          const std::vector<WallRegion>& regions,
                          const Model& current, const BasePlane* plane) {
  return FrameMeasurer(ed, samples, regions, current, plane).numbers();
}

}  // namespace pfdm
