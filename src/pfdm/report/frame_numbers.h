// One frame's numbers as AnalyzeFit measures them, and the same measurement
// kept for the delta method's steps (number_uncertainty.h), each of which
// moves one parameter a little: a knot's step moves the model only between
// the knot's neighbours (the parameter functions are piecewise linear over
// the knots), and a step of end-diastole's parameters moves no other
// frame's model (but for ED's spin, SpunWith).  What a step leaves is kept
// -- the region samples' rows and the cavity surfaces' vertices of the
// frame's model -- and only what it moves is measured again: the rows and
// vertices of a knot's span, 2 of the 16 spans of 17 knots.
#ifndef PFDM_REPORT_FRAME_NUMBERS_H_
#define PFDM_REPORT_FRAME_NUMBERS_H_

#include <limits>
#include <vector>

#include "pfdm/model/base_plane.h"
#include "pfdm/model/model.h"
#include "pfdm/model/model_surface.h"
#include "pfdm/report/clinical_summary.h"
#include "pfdm/report/global_strain.h"
#include "pfdm/report/reference_rings.h"
#include "pfdm/report/wall_motion.h"

namespace pfdm {

// One frame's numbers as AnalyzeFit measures them (before it leaves any
// out): against end-diastole's model `ed` and its samples, the volume
// closed by `plane` when given (a solid's cavity and myocardium).
struct FrameNumbers {
  ClinicalSummary clinical;
  std::vector<RegionMotion> regions;
  GlobalStrain strain;
};
FrameNumbers MeasureFrame(const Model& ed, const ReferenceSamples& samples,
                          const std::vector<WallRegion>& regions,
                          const Model& current, const BasePlane* plane);

// The range of u in which a model was moved.
struct MovedU {
  double low = -std::numeric_limits<double>::infinity();
  double high = std::numeric_limits<double>::infinity();
  // Whether the move may change the apex's or the base rim's height, by
  // which the segments' levels are cut (ResampleReference): a3 or e3o at
  // the first or the last knot, or anything but a knot.
  bool heights = true;
  // Whether the move is of the pose alone (a step of the center or the
  // rotation): the model's points and tangents turn and shift with it, and
  // a frame's kept samples and surfaces are moved rather than taken again.
  bool rigid = false;
};

// MeasureFrame of one frame's model `current`, kept.  `ed`, `samples`,
// `regions` and `plane` must outlive it.  Not thread-safe: Moved works on
// copies it keeps.
class FrameMeasurer {
 public:
  FrameMeasurer(const Model& ed, const ReferenceSamples& samples,
                const std::vector<WallRegion>& regions, const Model& current,
                const BasePlane* plane);
  const FrameNumbers& numbers() const { return numbers_; }
  // MeasureFrame(ed, samples, regions, moved, plane) for a `moved` that is
  // `current` outside `range`.
  FrameNumbers Moved(const Model& moved, const MovedU& range) const;
  // The same against another end-diastole, ed_rings.model() (ED's own
  // frame, which a step of ED's parameters moves as it moves the
  // reference), whose `samples` differ from the kept ones only where
  // ResampleReference takes `range`'s rows again: every row if
  // range.heights.  The frames measured against one moved end-diastole
  // share its rings.
  FrameNumbers Moved(const Model& moved, const MovedU& range,
                     ReferenceRings& ed_rings,
                     const ReferenceSamples& samples) const;
  // MeasureFrame(ed, samples, regions, current, plane) against another
  // end-diastole, `current` unchanged, `samples` as above.
  FrameNumbers Against(ReferenceRings& ed_rings,
                       const ReferenceSamples& samples,
                       const MovedU& range) const;

 private:
  // Moved, `samples` differing from the kept ones in the rows `rows` moves.
  FrameNumbers Moved(const Model& moved, const MovedU& range,
                     ReferenceRings& ed_rings, const ReferenceSamples& samples,
                     const MovedU& rows) const;
  // The kept samples and surfaces moved with `moved`'s pose.
  void MoveRigidly(const Model& moved) const;

  const Model& ed_;
  const ReferenceSamples& samples_;
  const std::vector<WallRegion>& regions_;
  const BasePlane* plane_;
  Model current_;
  CurrentSamples current_samples_;
  RegionComparison comparison_;
  // The cavity's surface (a solid's endocardium) and a solid's epicardium.
  std::vector<ModelSurface> surfaces_;
  // Their volumes, kept block by block of triangles.
  std::vector<KeptCavityVolume> volumes_;
  FrameNumbers numbers_;
  // ED's rings, which the frame's own steps measure against.
  mutable ReferenceRings ed_rings_;
  // Copies of the samples and surfaces that Moved changes and restores:
  // copied anew each step, their megabyte cost more in the allocator's
  // page faults than the measurement of a knot's span.
  mutable CurrentSamples moved_samples_;
  mutable std::vector<ModelSurface> moved_surfaces_;
};

}  // namespace pfdm

#endif  // PFDM_REPORT_FRAME_NUMBERS_H_
