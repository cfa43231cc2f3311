#include "pfdm/report/surface_view.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "pfdm/model/model_surface.h"
#include "pfdm/report/viewer_script.h"
#include "pfdm/util/stride.h"

namespace pfdm {
namespace {

struct Wall {
  double w;
  const char* name;
  const char* color;
  double opacity;
};

// A solid's walls, the endocardium drawn solid inside the epicardium's
// veil; one surface half see-through, so that the points behind it show.
std::vector<Wall> WallsOf(const Model& model) {
  if (model.config.Solid()) {
    return {{-1.0, "endocardium", "#d9794f", 1.0},
            {1.0, "epicardium", "#5b8fd9", 0.35}};
  }
  return {{0.0, "fitted surface", "#d9794f", 0.6}};
}

// Appends each coordinate as a whole count of `step` mm.
void AppendCoordinates(const Eigen::Vector3d& p, double step, bool* first,
                       std::ostringstream* out) {
  for (int i = 0; i < 3; ++i) {
    if (!*first) *out << ',';
    *first = false;
    *out << std::lround(p[i] / step);
  }
}

std::string FrameLabel(int t, const std::vector<double>& time_ms, int ed,
                       int es) {
  std::ostringstream label;
  label << "frame " << t;
  if (static_cast<int>(time_ms.size()) > t) {
    label << ", " << std::lround(time_ms[t]) << " ms";
  }
  if (t == ed) label << " (ED)";
  if (t == es) label << " (ES)";
  return label.str();
}

// Real time where the frames' times are known, within 40 to 400 ms a
// frame so that a cycle neither flickers nor crawls.
int FrameMs(const std::vector<double>& time_ms) {
  if (time_ms.size() < 2) return 120;
  const double step = (time_ms.back() - time_ms.front()) / (time_ms.size() - 1);
  return static_cast<int>(std::lround(std::clamp(step, 40.0, 400.0)));
}

size_t MostPoints(const PointSequence& points) {
  size_t most = 0;
  for (const Frame& frame : points.frames) {
    most = std::max(most, frame.points.size());
  }
  return most;
}

void AppendFrame(const Frame& frame, const Model& model,
                 const std::string& label, const SceneGrid& grid, int stride,
                 std::ostringstream* out) {
  *out << "{\"label\":\"" << label << "\",\"surfaces\":[";
  const std::vector<Wall> walls = WallsOf(model);
  for (size_t k = 0; k < walls.size(); ++k) {
    const ModelSurface surface =
        MakeModelSurface(model, grid.rings, grid.meridians, {}, walls[k].w);
    *out << (k ? ",[" : "[");
    bool first = true;
    for (const Eigen::Vector3d& p : surface.mesh.points) {
      AppendCoordinates(p, grid.step_mm, &first, out);
    }
    *out << ']';
  }
  *out << "],\"points\":[";
  bool first = true;
  for (size_t i = 0; i < frame.points.size(); i += stride) {
    AppendCoordinates(frame.points[i].position, grid.step_mm, &first, out);
  }
  *out << "]}";
}

}  // namespace

int PointStride(size_t num_points, int max_points) {
  if (max_points < 1) return 1;
  return static_cast<int>(
      StrideForAtMost(num_points, static_cast<size_t>(max_points)));
}

std::string SceneJson(const PointSequence& points,
                      const std::vector<Model>& models,
                      const std::vector<double>& time_ms, int ed_frame,
                      int es_frame, const SceneGrid& grid) {
  std::ostringstream out;
  out << "{\"scale\":" << grid.step_mm << ",\"rings\":" << grid.rings
      << ",\"meridians\":" << grid.meridians
      << ",\"frame_ms\":" << FrameMs(time_ms) << ",\"triangles\":[";
  const ModelSurface topology =
      MakeModelSurface(models.at(0), grid.rings, grid.meridians);
  bool first = true;
  for (const auto& triangle : topology.mesh.triangles) {
    for (int corner : triangle) {
      out << (first ? "" : ",") << corner;
      first = false;
    }
  }
  out << "],\"walls\":[";
  const std::vector<Wall> walls = WallsOf(models[0]);
  for (size_t k = 0; k < walls.size(); ++k) {
    out << (k ? "," : "") << "{\"name\":\"" << walls[k].name
        << "\",\"color\":\"" << walls[k].color
        << "\",\"opacity\":" << walls[k].opacity << '}';
  }
  const int stride = PointStride(MostPoints(points), grid.max_points);
  out << "],\"point_stride\":" << stride << ",\"frames\":[";
  for (size_t t = 0; t < models.size(); ++t) {
    if (t) out << ',';
    AppendFrame(points.frames.at(t), models[t],
                FrameLabel(static_cast<int>(t), time_ms, ed_frame, es_frame),
                grid, stride, &out);
  }
  out << "]}";
  return out.str();
}

std::string SurfaceViewHtml(const PointSequence& points, const SequenceFit& fit,
                            const FitAnalysis& analysis) {
  const EjectionFraction& ef = analysis.ejection_fraction;
  const int stride = PointStride(MostPoints(points), SceneGrid().max_points);
  std::ostringstream h;
  h << "<h2>The fitted ventricle and its data</h2>\n"
    << "<div id=\"pfdm-view3d\"><canvas style=\"width:720px;height:540px;"
       "max-width:100%;border:1px solid #ccc;touch-action:none\"></canvas>"
       "<div><button type=\"button\">Play</button> "
       "<input type=\"range\" min=\"0\" max=\"0\" value=\"0\" "
       "style=\"width:420px;vertical-align:middle\"> "
       "<span class=\"pfdm-frame\"></span></div></div>\n"
    << "<p class=\"note\">"
    << (fit.config.Solid() ? "The endocardium (orange) inside the "
                             "epicardium (blue)"
                           : "The fitted surface (orange)")
    << " of each frame with the frame's data points (red"
    << (stride > 1 ? ", 1 in " + std::to_string(stride) : std::string())
    << "). Drag to turn, "
       "the wheel to zoom; the slider or Play goes through the cycle.</p>\n"
    << "<script type=\"application/json\" id=\"pfdm-scene\">"
    << SceneJson(points, analysis.models, fit.time_ms, ef.ed_frame, ef.es_frame)
    << "</script>\n<script>" << kViewerScript << "</script>\n";
  return h.str();
}

}  // namespace pfdm
