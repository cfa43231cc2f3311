// report.html's 3D view: each frame's fitted surfaces and data points as a
// JSON scene the page's script (report/viewer_script.h) draws with
// three.js, rotated, zoomed and played through the cycle.
#ifndef PFDM_REPORT_SURFACE_VIEW_H_
#define PFDM_REPORT_SURFACE_VIEW_H_

#include <string>
#include <vector>

#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/model/model.h"
#include "pfdm/report/fit_analysis.h"
#include "pfdm/util/point_data.h"

namespace pfdm {

// How finely the surfaces are sampled, and the coordinates' step: coarse
// enough that 25 frames of 2,000 points stay near 1.5 MB with the script
// (docs/report.md), fine enough to see the shape.
struct SceneGrid {
  int rings = 24;
  int meridians = 36;
  double step_mm = 0.1;
  // A frame of more points shows every k-th (PointStride): 50,000 tags
  // would make a page of tens of MB.
  int max_points = 4000;
};

// 1, or the k that leaves at most max_points of num_points.
int PointStride(size_t num_points, int max_points);

// {"scale": step_mm, "rings", "meridians", "frame_ms": the playing speed,
//  "triangles": [i, j, k, ...] (one topology for every surface),
//  "walls": [{"name", "color", "opacity"}] (a solid's endocardium and
//  epicardium, else the one fitted surface, sampled by MakeModelSurface),
//  "point_stride": the largest frame's PointStride, "frames": [{"label",
//  "surfaces": [[x, y, z, ...] per wall], "points": [x, y, z, ...] (every
//  point_stride-th)}]}
// with every coordinate an integer count of step_mm.  ED and ES are named in
// their frames' labels, with the time where time_ms gives one per frame.
std::string SceneJson(const PointSequence& points,
                      const std::vector<Model>& models,
                      const std::vector<double>& time_ms, int ed_frame,
                      int es_frame, const SceneGrid& grid = SceneGrid());

// The page's section: the canvas, the frame slider and play button, the
// scene's JSON and the script.
std::string SurfaceViewHtml(const PointSequence& points, const SequenceFit& fit,
                            const FitAnalysis& analysis);

}  // namespace pfdm

#endif  // PFDM_REPORT_SURFACE_VIEW_H_
