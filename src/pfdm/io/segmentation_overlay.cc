#include "pfdm/io/segmentation_overlay.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "Eigen/LU"
#include "pfdm/util/angles.h"

namespace pfdm {

namespace {

constexpr int kSteps = 400;
constexpr double kPixel = 3.0;  // SVG units per voxel.

// The kept slices of frame 0 at the apex's end, the middle and the base.
std::vector<int> ShownSlices(const MaskContours& contours, int nz) {
  std::vector<int> kept;
  for (int k = 0; k < nz; ++k) {
    if (contours.rings[k].kept && contours.rings[k].has_cavity) {
      kept.push_back(k);
    }
  }
  if (kept.size() <= 3) return kept;
  return {kept.front(), kept[kept.size() / 2], kept.back()};
}

void Panel(const LabelVolume& volume, const LabelMap& labels,
           const Model& model, int k, int t, double x0, double y0,
           std::ostringstream* svg) {
  *svg << "<g transform=\"translate(" << x0 << "," << y0 << ")\">\n";
  *svg << "<rect width=\"" << volume.nx * kPixel << "\" height=\""
       << volume.ny * kPixel << "\" fill=\"black\"/>\n";
  for (int j = 0; j < volume.ny; ++j) {
    for (int i = 0; i < volume.nx; ++i) {
      const std::int32_t v = volume.At(i, j, k, t);
      const char* colour = v == labels.lv    ? "#a33"
                           : v == labels.myo ? "#3a3"
                           : v == labels.rv  ? "#35a"
                                             : nullptr;
      if (colour == nullptr) continue;
      *svg << "<rect x=\"" << i * kPixel << "\" y=\"" << j * kPixel
           << "\" width=\"" << kPixel << "\" height=\"" << kPixel
           << "\" fill=\"" << colour << "\"/>\n";
    }
  }
  for (const auto& [w, colour] :
       {std::make_pair(-1.0, "yellow"), std::make_pair(1.0, "white")}) {
    for (const Eigen::Vector2d& p : WallCut(model, w, volume, k)) {
      *svg << "<circle cx=\"" << (p.x() + 0.5) * kPixel << "\" cy=\""
           << (p.y() + 0.5) * kPixel << "\" r=\"1.2\" fill=\"" << colour
           << "\"/>\n";
    }
  }
  *svg << "<text x=\"4\" y=\"14\" fill=\"white\" font-size=\"12\">frame " << t
       << ", slice " << k << "</text>\n</g>\n";
}

}  // namespace

std::vector<Eigen::Vector2d> WallCut(const Model& model, double w,
                                     const LabelVolume& volume, int k,
                                     int meridians) {
  const Eigen::Matrix4d voxel_from_world = volume.world_from_voxel.inverse();
  // Signed slice coordinate of a world point minus k.
  auto across = [&](const Eigen::Vector3d& x) {
    return (voxel_from_world * x.homogeneous())(2) - k;
  };
  const double u0 = model.config.u_min, u1 = model.config.u_max;
  std::vector<Eigen::Vector2d> cut;
  for (int m = 0; m < meridians; ++m) {
    const double v = -kPi + 2.0 * kPi * m / meridians;
    Eigen::Vector3d before = model.WorldPoint(u0, v, w);
    double s_before = across(before);
    for (int n = 1; n <= kSteps; ++n) {
      const Eigen::Vector3d x =
          model.WorldPoint(u0 + (u1 - u0) * n / kSteps, v, w);
      const double s = across(x);
      if ((s < 0.0) != (s_before < 0.0)) {
        const Eigen::Vector3d p =
            before + (x - before) * (s_before / (s_before - s));
        cut.push_back((voxel_from_world * p.homogeneous()).head<2>());
        break;
      }
      before = x;
      s_before = s;
    }
  }
  return cut;
}

std::string SegmentationOverlaySvg(const LabelVolume& volume,
                                   const LabelMap& labels,
                                   const MaskContours& contours,
                                   const std::vector<Model>& models,
                                   int es_frame) {
  const std::vector<int> slices = ShownSlices(contours, volume.nz);
  std::vector<int> frames{0};
  if (es_frame > 0 && es_frame < static_cast<int>(models.size())) {
    frames.push_back(es_frame);
  }
  const double width = volume.nx * kPixel + 8, height = volume.ny * kPixel + 8;
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\""
      << width * slices.size() << "\" height=\"" << height * frames.size()
      << "\">\n";
  for (size_t r = 0; r < frames.size(); ++r) {
    for (size_t c = 0; c < slices.size(); ++c) {
      Panel(volume, labels, models[frames[r]], slices[c], frames[r], c * width,
            r * height, &svg);
    }
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace pfdm
