// Basal short-axis contours beside the ventricle's axis, not round it.  As
// the base rises and falls over the cycle, the most basal short-axis plane
// can catch the outflow tract alone: a small ring beside the axis, not
// round it.  The model is a ring about its axis at every height, and such a
// ring pulls one side of its top knots in with nothing holding the other:
// on biv-me patient 1, frame 13's slice 2 (31 points on a ring of 14 mm
// radius, the axis outside it) collapsed the base's x radius from 17.5 to
// 6.2 mm at the last knot, the basal strains jumped by 14 points for that
// frame alone, and the cavity read 8 % under biv-me's mesh
// (docs/contour_sequences.md).  Such contours are left out of the fit, and
// the sequence records which (PointSequence::left_out).
#ifndef PFDM_IO_PARTIAL_RINGS_H_
#define PFDM_IO_PARTIAL_RINGS_H_

#include <string>
#include <vector>

#include "Eigen/Core"
#include "pfdm/util/point_data.h"

namespace pfdm {

// Seen from the axis, a ring leaving a gap wider than this does not go
// round it: biv-me patient 1's basal endocardial rings leave 10-21
// degrees, its two outflow-tract ones 211 and 294.  But its epicardial
// contours are the free wall's arcs (the septum is the RV's), which leave
// about 135 degrees with their centre on the axis: a ring is also beside
// the axis only when its circle's centre lies more than kBesideAxisRadii
// radii from it (the outflow tract's 1.02 and 2.10; the basal endocardial
// rings' 0.27-0.51, the epicardial arcs' 0.11-0.34).
inline constexpr double kPartialRingGapDeg = 90.0;
inline constexpr double kBesideAxisRadii = 0.75;
// Fewer rings of a type than this leave every ring in (the base's end is
// told by the rings next to the ends).
inline constexpr size_t kMinRingsJudged = 4;

// A ring's least-squares plane (e1, e2) and circle in it.
struct RingCircle {
  std::string contour;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 0.0;
  Eigen::Vector3d e1 = Eigen::Vector3d::UnitX();
  Eigen::Vector3d e2 = Eigen::Vector3d::UnitY();
};
// At least 3 points.
RingCircle FitRingCircle(const std::vector<Eigen::Vector3d>& ring);

// The widest angle between neighbouring points of `ring`, seen from `from`
// in the plane of `plane`, degrees; 360 for fewer than 2 points.
double LargestGapDeg(const std::vector<Eigen::Vector3d>& ring,
                     const RingCircle& plane, const Eigen::Vector3d& from);

// One frame's points and, per point, its contour ("SAX_LV_ENDOCARDIAL 2":
// the contour type and its slice).  Per short-axis type ("SAX_" types)
// with at least kMinRingsJudged rings of 3 points or more: the rings are
// ordered along the line through their centres, the base at the end where they
// are wider; the most basal one lies beside the axis when, seen from the line
// through the other rings' centres, it leaves a gap wider than
// kPartialRingGapDeg and its centre lies more than kBesideAxisRadii of its
// radius from that line. That slice's short-axis contours of every type are
// then dropped from *points and recorded in *left_out (its coverage seen from
// that line): the plane holds the outflow tract, and its epicardial arc kept
// alone still pulled biv-me's frame 13 basal Ecc 4.4 points off its neighbours.
// Other contours are kept as they are.
void LeaveOutPartialRings(int frame, const std::vector<std::string>& contours,
                          std::vector<DataPoint>* points,
                          std::vector<LeftOutContour>* left_out);

}  // namespace pfdm

#endif  // PFDM_IO_PARTIAL_RINGS_H_
