// The fit's verdict on each frame (FrameFit::verdict): what the solve
// itself shows that the solver's termination does not.  Each reason
// measures one thing against a stated bound (docs/verdict.md):
//   solver       the solver stopped without converging;
//   unsettled    closest points still moving, when the rounds ran out, by
//                more than the frames' median RMS (the data's noise as the
//                fit sees it);
//   rms_frames   RMS far above the sequence's other frames;
//   rms_size     RMS a large share of the data's own size;
//   prior        the prior holding the model where the data of tags would
//                move it: one solver step from the solution without the
//                prior moves the points by a share of the frame's RMS;
//   at_bound     a shape function pressed against its bound;
//   walls_meet   a solid's thickness h at its floor 0 below the top knot;
//   sparse_rings knot spans inside the data with almost no points;
//   short_span   a later frame's data spanning much less of the axis than
//                frame 0's (contours that lost a slice);
//   not_moved    frame 0's solve never left its start;
//   extrapolated no data near the apex (SequenceFit::apex_in_data);
//   top_slice    the highest data one short-axis slice: the base not in
//                the data (top_slice.h; not asked of a segmentation's,
//                whose labels close the base);
//   axis_across  the model's long axis across an elongated cloud's length
//                (cloud_length.h);
//   flat_data    points nearly in a plane, no ventricle;
//   two_surfaces one surface through tags and contours that lie on two
//                (mid-wall tags beside one wall's contours).
// The clinical numbers' plausibility is the analysis' (report/).
#ifndef PFDM_FIT_STAGES_FRAME_VERDICT_H_
#define PFDM_FIT_STAGES_FRAME_VERDICT_H_

#include <vector>

#include "pfdm/fit/fit_options.h"
#include "pfdm/fit/stages/frame_points.h"
#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/util/point_data.h"

namespace pfdm {

// Warning above, failed above the second bound.
constexpr double kUnsettledFailMm = 10.0;
constexpr double kRmsFramesRatio = 3.0;  // Times the frames' median RMS ...
constexpr double kRmsFramesMinMm = 1.0;  // ... and this much above it.
// A mid-wall surface forced onto tags through a 10 mm wall (--wall
// midwall) reads 7-12 %: a warning, its numbers the mid-wall's.
constexpr double kRmsSizeWarn = 0.06, kRmsSizeFail = 0.2;
// The step without the prior, RMS over the points, as a share of the
// frame's RMS.
constexpr double kPriorPullWarn = 0.25, kPriorPullFail = 1.0;
// A step under this moves no point by anything an image or a tracker
// resolves (a fifteenth of a 1.5 mm voxel): on the LV phantom's noise-free
// tags a frame's RMS is 0.002-0.06 mm, and a step of 0.01-0.06 mm read as
// 75-110 % of it, "failed".
constexpr double kPriorPullFloorMm = 0.1;
// With a robust loss, the points it weighs at least kKeptWeight are the
// ones the RMS reasons judge (a point 2 scales off under huber, 1 under
// cauchy); more than kDownWeightedWarn of them weighed below it is a
// warning: more outliers than a tracker makes.
constexpr double kKeptWeight = 0.5, kDownWeightedWarn = 0.2;
constexpr int kMinRingPoints = 3;
// A later frame's data span along the axis, as a share of frame 0's: 9
// short-axis slices that lose the basal one keep 7/8.
constexpr double kMinSpanShare = 0.75;
// The code of that warning: the analysis leaves such a frame's volumes out.
inline constexpr char kShortSpanCode[] = "short_span";
constexpr double kFlatDataRatio = 0.02;
inline constexpr char kTopSliceCode[] = "top_slice";
inline constexpr char kAxisAcrossCode[] = "axis_across";
// One surface fitted to tags and contours: the mean signed distance of the
// tags from it less the contours', over this, fails.  Mid-wall tags beside
// the endocardium's contours (the LV phantom, 400 tags) lie half a wall
// (4-5 mm) outward of them, and one surface between read EDV 134 ml
// against the cavity's 107 and the mid-wall's 163, frame 0's verdict ok;
// tags and contours of one surface differ by noise.
constexpr double kTwoSurfacesMm = 2.0;
// A solid's frame without contours of either wall whose tags' rms depth is
// under this warns with kWallsUnseenCode, and the analysis leaves its
// walls' numbers out: mid-wall tags (rms 0.13 on the LV phantom) beside
// both walls' contours at ED and ES alone read thickening -14 to -20 %
// between them (truth 13.5 and 27) and the cavity 10-16 % large.  Tags
// through the wall fill it (1/sqrt(3) = 0.58; measured beside the
// contours 0.54-0.59).
constexpr double kWallSpanningDepthRms = 0.35;
inline constexpr char kWallsUnseenCode[] = "walls_unseen";

// The RMS (mm) of the material points' move from `before` to `after`,
// over every k-th of them, at most kMoveSamples: an RMS of thousands of
// moves is known to a percent or two, and two model evaluations a point
// were a fifth of the prior's probe at 20,000 tags.
constexpr size_t kMoveSamples = 4096;
double RmsMoveMm(const Model& before, const Model& after,
                 const std::vector<MaterialPoint>& material);

// Adds the fit's reasons to every frame's verdict.  `frames_per_id` the
// sequence's (CountFramesPerId), `options` as the fit had them.
void JudgeFrames(const PointSequence& sequence,
                 const FramesPerId& frames_per_id, const FitOptions& options,
                 SequenceFit* fit);

}  // namespace pfdm

#endif  // PFDM_FIT_STAGES_FRAME_VERDICT_H_
