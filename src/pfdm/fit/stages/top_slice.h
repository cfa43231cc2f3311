// Whether a frame's highest data are one short-axis slice: a flat ring all
// round the axis with nothing above it.  The fit's model then ends at that
// slice (its length reaches the highest data), and so do its basal rings
// and the volumes, wherever the base lies above it: on the LV phantom's
// endocardial short-axis stack without long-axis planes (`pfdm simulate
// --phantom lv --sampling sax-slices --wall_tags endo`, slices from 5 to
// 90 % of the length) EDV read 95 ml against the truth's 107, every frame
// otherwise ok.  Long-axis contours reach the base and end in a few
// points, not a ring; tags fill the wall's height, not a plane.
#ifndef PFDM_FIT_STAGES_TOP_SLICE_H_
#define PFDM_FIT_STAGES_TOP_SLICE_H_

#include <vector>

#include "Eigen/Core"
#include "pfdm/model/model.h"

namespace pfdm {

// The top band: points within kTopBandMm of the highest along the axis;
// under a short-axis stack's slice spacing (8-10 mm), over a slice's own
// spread (its noise, and its tilt from the fitted axis over part of the
// ring).
constexpr double kTopBandMm = 5.0;
// The band is a slice when its points lie within kTopPlaneRmsMm (rms) of a
// plane at most kTopSliceTiltDeg from square to the axis, and at most
// kMaxOffSliceShare of them farther than kOnSliceMm.  A contour lies in its
// image plane (the LV phantom's slices, noise in the plane: 0.0 mm); tags
// filling a 5 mm band read about 1.4 mm, 16 tags on a mid-wall surface 0.9
// (`pfdm simulate --tags 300`); long-axis contours that end within a few
// mm of the top slice (the base there) put their points below it into the
// band (6 % of it on the LV phantom).
constexpr double kTopPlaneRmsMm = 0.5;
constexpr double kOnSliceMm = 2.0;
constexpr double kMaxOffSliceShare = 0.02;
constexpr double kTopSliceTiltDeg = 30.0;
constexpr int kMinTopPoints = 12;
// All round: the points within kOnSliceMm of that plane fill at least
// kMinTopSectors of kTopSectors about the axis (a basal ring cut by the
// outflow tract keeps 3/4 of it; three long-axis planes' tops fill 6), and
// no point lies more than kOnSliceMm above it.
constexpr int kTopSectors = 12, kMinTopSectors = 9;
// Fewer where the points on the plane are few (NeededTopSectors), but
// never as few as three long-axis planes' tops fill.
constexpr int kMinSparseTopSectors = 7;

struct TopSlice {
  bool found = false;            // The highest data are one short-axis slice.
  int points = 0;                // In the top band.
  double rms_mm = 0.0;           // Of the band's points from their plane.
  double off_slice_share = 0.0;  // Of them farther than kOnSliceMm.
  double tilt_deg = 0.0;         // The plane's normal from the axis.
  // Of kTopSectors holding a point on the plane; -1: a point lies above it.
  int sectors = 0;
  int needed_sectors = kMinTopSectors;  // NeededTopSectors of those points.
};

// How many sectors the band's points on the plane must fill to be all
// round: the mean count n points at random round a whole ring fill, S (1 -
// (1 - 1/S)^n) of S sectors, less two of its sds, between
// kMinSparseTopSectors and kMinTopSectors.  A slice of 16 points (the LV
// phantom's top slice of both walls at 150 points a frame) fills 9.0 +-
// 1.1 of 12, and a flat kMinTopSectors failed it in over a quarter of the
// fits, the solid's rim then dropping by its wall's drop (RimLift, about 1
// mm) between one fit and the next: on 100 noise draws the later frame's
// a3 read 0.9-1.3 mm off the noise-free fit's in 9 (the rest within 0.4).
int NeededTopSectors(int points_on_plane);

// `axis`: the model's long axis (unit, apex to base) through `on_axis`, in
// the points' frame.  The sectors are about it: about the points' own
// centroid, half a ring would fill two thirds of them.
TopSlice FindTopSlice(const std::vector<Eigen::Vector3d>& points,
                      const Eigen::Vector3d& on_axis,
                      const Eigen::Vector3d& axis);

// How far above the highest data a model's mid-wall rim ends (the rim's
// target in SpanAxialExtent and the rim residual): a solid's LowestRimDrop
// where the data end at one short-axis slice (top_is_slice, FindTopSlice's
// `found`), so that every wall's rim reaches the slice each wall's contours
// reach; 0 for a surface and where the top is not a slice (the LV phantom's
// tags through the wall end on a surface across it, as the walls' rims do).
// With the mid-wall's rim at the slice, the endocardium's lay 1.5 mm below
// it: frame 0 of the noise-free LV phantom's both walls' short-axis contours
// read RMS 0.47 mm, the top slice's endocardial points 1.28 mm off.
double RimLift(bool top_is_slice, const Model& model);

// FindTopSlice's `found` about the model's axis through its centre.
bool TopIsSlice(const std::vector<Eigen::Vector3d>& points, const Model& model);

}  // namespace pfdm

#endif  // PFDM_FIT_STAGES_TOP_SLICE_H_
