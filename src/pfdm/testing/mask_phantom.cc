#include "pfdm/testing/mask_phantom.h"

#include <cmath>
#include <optional>

#include "pfdm/phantom/lv_slices.h"
#include "pfdm/util/angles.h"

namespace pfdm {

namespace {

constexpr int kMeridians = 360;

using Polygon = std::vector<Eigen::Vector2d>;

bool Inside(const Polygon& polygon, const Eigen::Vector2d& p) {
  bool inside = false;
  for (size_t a = 0, b = polygon.size() - 1; a < polygon.size(); b = a++) {
    const Eigen::Vector2d& u = polygon[a];
    const Eigen::Vector2d& v = polygon[b];
    if ((u.y() > p.y()) != (v.y() > p.y()) &&
        p.x() < (v.x() - u.x()) * (p.y() - u.y()) / (v.y() - u.y()) + u.x()) {
      inside = !inside;
    }
  }
  return inside;
}

// Surface w's cut by the slice in voxel (i, j), empty when a meridian
// misses the plane.
Polygon Cut(const LvShape& shape, const LvPhantomOptions& options,
            const LvFrameMotion& motion, const LvImagePlane& plane, double w,
            const Eigen::Matrix4d& voxel_from_world) {
  Polygon polygon;
  for (int m = 0; m < kMeridians; ++m) {
    const double phi = -kPi + 2.0 * kPi * m / kMeridians;
    const std::optional<Eigen::Vector3d> cut =
        SliceCut(shape, options.deformation, motion, plane, phi, w);
    if (!cut) return {};
    polygon.push_back((voxel_from_world * cut->homogeneous()).head<2>());
  }
  return polygon;
}

double Distance(const Polygon& polygon, const Eigen::Vector2d& p) {
  double best = 1e300;
  for (const Eigen::Vector2d& v : polygon)
    best = std::min(best, (v - p).norm());
  return best;
}

// One slice of one frame, labelled.
void LabelSlice(const Polygon& endo, const Polygon& epi,
                const MaskPhantomOptions& options, int k, int t,
                LabelVolume* volume) {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& v : epi) centre += v;
  if (!epi.empty()) centre /= epi.size();
  const double rv_reach = 12.0 / options.in_plane_mm;
  for (int j = 0; j < volume->ny; ++j) {
    for (int i = 0; i < volume->nx; ++i) {
      const Eigen::Vector2d p(i, j);
      std::int32_t label = 0;
      if (!endo.empty() && Inside(endo, p)) {
        label = options.labels.lv;
      } else if (!epi.empty() && Inside(epi, p)) {
        label = options.labels.myo;
      } else if (!epi.empty()) {
        const double phi = std::atan2(p.y() - centre.y(), p.x() - centre.x());
        if (phi < -kPi / 3.0 && Distance(epi, p) < rv_reach) {
          label = options.labels.rv;
        }
      }
      volume->labels[volume->Index(i, j, k, t)] = label;
    }
  }
}

void Shift(const MaskPhantomOptions& options, LabelVolume* volume) {
  const int k = options.shifted_slice;
  for (int t = 0; t < volume->nt; ++t) {
    for (int j = 0; j < volume->ny; ++j) {
      std::vector<std::int32_t> row(volume->nx, 0);
      for (int i = 0; i < volume->nx; ++i) {
        const int from = i - options.shift_voxels;
        if (from >= 0 && from < volume->nx) row[i] = volume->At(from, j, k, t);
      }
      for (int i = 0; i < volume->nx; ++i) {
        volume->labels[volume->Index(i, j, k, t)] = row[i];
      }
    }
  }
}

}  // namespace

MaskPhantom MakeMaskPhantom(const MaskPhantomOptions& options) {
  LvPhantomOptions lv;
  lv.num_frames = options.num_frames;
  lv.tags = LvTagLayer::kWall;
  lv.num_tags = 200;
  lv.noise_mm = 0.0;
  lv.breathing = options.breathing;
  MaskPhantom mask{MakeLvPhantom(lv), {}, {}, {}, {}};
  const LvShape shape(lv.shape);
  mask.world_from_body0 = mask.phantom.truth[0].world_from_body;
  // From half a slice below the epicardial apex to past the base.
  const double z0 = shape.ApexZ(1.0) + 0.5 * options.slice_mm;
  const int nz =
      static_cast<int>(std::ceil((shape.base_z() - z0) / options.slice_mm)) + 2;
  LabelVolume& volume = mask.volume;
  volume.source = "mask phantom";
  volume.nx = volume.ny = options.size;
  volume.nz = nz;
  volume.nt = options.num_frames;
  volume.labels.assign(
      static_cast<size_t>(volume.nx) * volume.ny * nz * volume.nt, 0);
  const Eigen::Matrix3d r = mask.world_from_body0.linear();
  const double half = 0.5 * (options.size - 1) * options.in_plane_mm;
  volume.world_from_voxel.topLeftCorner<3, 3>()
      << r.col(0) * options.in_plane_mm,
      r.col(1) * options.in_plane_mm, r.col(2) * options.slice_mm;
  volume.world_from_voxel.topRightCorner<3, 1>() =
      mask.world_from_body0 * Eigen::Vector3d(-half, -half, z0);
  volume.geometry = "sform";
  const Eigen::Matrix4d voxel_from_world = volume.world_from_voxel.inverse();
  for (int t = 0; t < volume.nt; ++t) {
    const LvFrameMotion motion =
        ScenarioMotion(lv.kinematics, t, volume.nt, lv.breathing);
    for (int k = 0; k < nz; ++k) {
      const LvImagePlane plane =
          ShortAxisPlane(mask.world_from_body0, z0 + k * options.slice_mm);
      LabelSlice(Cut(shape, lv, motion, plane, -1.0, voxel_from_world),
                 Cut(shape, lv, motion, plane, 1.0, voxel_from_world), options,
                 k, t, &volume);
    }
  }
  if (options.shifted_slice >= 0) Shift(options, &volume);
  const size_t per_frame = volume.labels.size() / volume.nt;
  for (int t = 0; t < volume.nt; ++t) {
    int cavity = 0, myocardium = 0;
    for (size_t n = per_frame * t; n < per_frame * (t + 1); ++n) {
      cavity += volume.labels[n] == options.labels.lv;
      myocardium += volume.labels[n] == options.labels.myo;
    }
    mask.cavity_ml.push_back(cavity * volume.VoxelVolumeMl());
    mask.myocardium_ml.push_back(myocardium * volume.VoxelVolumeMl());
  }
  return mask;
}

}  // namespace pfdm
