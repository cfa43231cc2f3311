// A frame's correspondences as the fit's rounds update them: the listed
// points' closest material points, each sought on its own surface of a
// solid, and tags re-ranked across the wall.
#ifndef PFDM_FIT_CORRESPONDENCE_FRAME_CORRESPONDENCE_H_
#define PFDM_FIT_CORRESPONDENCE_FRAME_CORRESPONDENCE_H_

#include <cstddef>
#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/model/model.h"

namespace pfdm {

class SurfaceGrid;  // surface_grid.h

// The listed points' material points.
std::vector<MaterialPoint> Listed(const std::vector<MaterialPoint>& material,
                                  const std::vector<size_t>& which);

// The largest distance (mm) between paired points.
double MaxDistance(const std::vector<Eigen::Vector3d>& a,
                   const std::vector<Eigen::Vector3d>& b);

// How tags through a wall get their depth w (transmural.h): measured across
// a wall the contours place (measured_depths.h), ranked in their
// band of latitude (QuantileDepths), or among their nearest tags
// (NeighbourhoodDepths: a solid with a transmural local field whose tags
// are ranked in every frame, where a segment may move unlike its ring);
// with a robust loss, only the tags
// within the wall widened by outlier_band_mm (WithinWall) are ranked.
struct DepthRanking {
  double outlier_band_mm = 0.0;  // 0: every tag ranked.
  bool neighbourhoods = false;
  // UpdateClosest: a warm search keeps each assigned depth (the material
  // point's w) and seeks the tag on that layer alone, unranked.
  bool hold = false;
  // The frame's contours place both walls (HasBothWalls): a tag's depth is
  // where it lies across the fitted wall (MeasuredDepths), not its rank.
  bool measured = false;
};

// Fills material[i] for the listed points with their closest material
// points, normals[i] with the normals they pull along (zero where they do
// not: PullsAlongNormal) and found[j] with their model points, in the
// listed order.  In a solid, a point is sought on its surface: layer_w[i]
// for a contour of one wall, or, when depths are assigned (frame 0's tags),
// their ranked depth, or their held one (DepthRanking).
// `warm` starts each search from the point's current material point.
// `grid` (may be null: one is built for the search) follows `model` and
// keeps its tree for the next search (SurfaceGrid::Follow).
void UpdateClosest(
    const Model& model, const std::vector<Eigen::Vector3d>& points,
    const std::vector<size_t>& which, int num_threads,
    const std::vector<double>& layer_w, const std::vector<bool>& assign_depth,
    bool warm, std::vector<MaterialPoint>* material,
    std::vector<Eigen::Vector3d>* normals, std::vector<Eigen::Vector3d>* found,
    const DepthRanking& ranking = DepthRanking(), SurfaceGrid* grid = nullptr);

// Sets the listed points' w to their ranked depths on `model` and, when
// moved_mm is not null, says how far (mm) the farthest one's model point
// moved (two evaluations of every model point: half the ranking's cost).  Why
// each frame ranks its tags afresh rather than keeping frame 0's w: a w read
// from noisy distances regresses every later frame's thickness toward zero
// (errors in the regressor), by the noise's share of the depths' variance,
// while frame 0's own h comes out inflated by as much; ranked in every frame, h
// is biased alike in all of them and the thickening (a ratio) is not.  A tag's
// place in the order across the wall is material; its rank changes only by
// noise.
void RerankDepths(const Model& model,
                  const std::vector<Eigen::Vector3d>& points,
                  const std::vector<size_t>& which,
                  std::vector<MaterialPoint>* material,
                  const DepthRanking& ranking = DepthRanking(),
                  double* moved_mm = nullptr);

}  // namespace pfdm

#endif  // PFDM_FIT_CORRESPONDENCE_FRAME_CORRESPONDENCE_H_
