#include "pfdm/segmentation/mask_contours.h"

#include <algorithm>
#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/testing/mask_phantom.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;

const MaskPhantom& Phantom() {
  static const MaskPhantom* phantom =
      new MaskPhantom(MakeMaskPhantom(MaskPhantomOptions()));
  return *phantom;
}

// Body longitude (degrees) of a world point at frame 0.
double Longitude(const MaskPhantom& mask, const Eigen::Vector3d& world) {
  const Eigen::Vector3d body = mask.world_from_body0.inverse() * world;
  return std::atan2(body.y(), body.x()) * kDeg;
}

// The phantom's stack: apex at slice 0, the base where the ring last
// closes, both walls' points on their surfaces' cuts.
TEST(MaskContoursTest, PhantomStackWalls) {
  const MaskPhantom& mask = Phantom();
  const MaskContours c = ExtractMaskContours(mask.volume, LabelMap());
  EXPECT_EQ(c.apex_slice, 0);
  ASSERT_EQ(c.base_slice.size(), 3u);
  // Systole moves the base toward the apex by 17 % of 95 mm: about two
  // slices of 8 mm lose their ring.
  EXPECT_GT(c.base_slice[0], c.base_slice[2]);
  EXPECT_LE(c.base_slice[0], mask.volume.nz - 1);
  // The labels close the base, so the fit does not warn that a slice ends
  // the data (fit/stages/top_slice.h).
  EXPECT_TRUE(c.points.base_from_labels);
  ASSERT_EQ(c.points.frames.size(), 3u);
  int endo = 0, epi = 0;
  for (const DataPoint& p : c.points.frames[0].points) {
    endo += p.layer == WallLayer::kEndocardium;
    epi += p.layer == WallLayer::kEpicardium;
  }
  std::printf("slices %d, base %d %d %d, endo %d epi %d points\n",
              mask.volume.nz, c.base_slice[0], c.base_slice[1], c.base_slice[2],
              endo, epi);
  EXPECT_GT(endo, 500);
  EXPECT_GT(epi, endo);
  EXPECT_DOUBLE_EQ(c.slice_thickness_mm, 8.0);
  EXPECT_TRUE(c.misaligned.empty()) << c.warnings.front();
  // The cavity centres of the unshifted stack lie on a line: each within
  // 0.5 mm of its neighbours' (kMisalignedMm's margin).
  const int nz = mask.volume.nz;
  const Eigen::Vector3d normal =
      mask.volume.world_from_voxel.col(2).head<3>().normalized();
  double worst = 0.0;
  for (int t = 0; t < 3; ++t) {
    for (int k = 2; k < c.base_slice[t]; ++k) {
      const Eigen::Vector3d& a = c.rings[t * nz + k - 1].cavity_centroid;
      const Eigen::Vector3d& b = c.rings[t * nz + k + 1].cavity_centroid;
      Eigen::Vector3d off = c.rings[t * nz + k].cavity_centroid - 0.5 * (a + b);
      off -= normal * normal.dot(off);
      worst = std::max(worst, off.norm());
    }
  }
  std::printf("cavity centres off their neighbours' line: %.2f mm at most\n",
              worst);
  EXPECT_LT(worst, 0.5);
}

// The contact arc's ends are the phantom's insertions, at body longitude
// -60 and -180 degrees, within 8 degrees.
TEST(MaskContoursTest, RvInsertionAtThePhantomsLongitudes) {
  const MaskPhantom& mask = Phantom();
  const MaskContours c = ExtractMaskContours(mask.volume, LabelMap());
  ASSERT_GE(c.rv_insertion.size(), 10u);
  ASSERT_EQ(c.rv_insertion.size() % 2, 0u);
  for (size_t n = 0; n < c.rv_insertion.size(); n += 2) {
    double a = Longitude(mask, c.rv_insertion[n]);
    double b = Longitude(mask, c.rv_insertion[n + 1]);
    if (std::abs(a + 60.0) > std::abs(b + 60.0)) std::swap(a, b);
    EXPECT_NEAR(a, -60.0, 8.0) << "slice pair " << n / 2;
    EXPECT_GT(std::abs(b), 172.0) << "slice pair " << n / 2;
  }
}

// A slice moved 6 mm in-plane (4 voxels) is named in every frame.
TEST(MaskContoursTest, ShiftedSliceIsNamed) {
  MaskPhantomOptions options;
  options.shifted_slice = 6;
  options.shift_voxels = 4;
  const MaskPhantom mask = MakeMaskPhantom(options);
  const MaskContours c = ExtractMaskContours(mask.volume, LabelMap());
  ASSERT_EQ(c.misaligned.size(), 1u);
  EXPECT_EQ(c.misaligned[0].slice, 6);
  EXPECT_EQ(c.misaligned[0].frames.size(), 3u);
  EXPECT_NEAR(c.misaligned[0].max_offset_mm, 6.0, 1.0);
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_NE(c.warnings[0].find("slice 6:"), std::string::npos);
}

// The mean of frame t's points in slice k's plane (its world height
// along the slices' normal within 1 mm).
Eigen::Vector3d SliceCentre(const MaskContours& c, const LabelVolume& v, int t,
                            int k) {
  const Eigen::Vector3d normal = v.world_from_voxel.col(2).head<3>();
  const double height = v.World(0, 0, k).dot(normal.normalized());
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int n = 0;
  for (const DataPoint& p : c.points.frames[t].points) {
    if (std::abs(p.position.dot(normal.normalized()) - height) > 1.0) continue;
    sum += p.position;
    ++n;
  }
  return sum / std::max(n, 1);
}

// The shifted slice's contours come back onto the stack: their centre
// within 0.5 mm of the unshifted mask's in every frame (6 mm before).
TEST(MaskContoursTest, ShiftedSliceIsMovedBack) {
  MaskPhantomOptions options;
  const MaskPhantom straight = MakeMaskPhantom(options);
  options.shifted_slice = 6;
  options.shift_voxels = 4;
  const MaskPhantom shifted = MakeMaskPhantom(options);
  const MaskContours a = ExtractMaskContours(straight.volume, LabelMap());
  const MaskContours b = ExtractMaskContours(shifted.volume, LabelMap());
  ASSERT_EQ(b.misaligned.size(), 1u);
  ASSERT_EQ(b.misaligned[0].shifts.size(), 3u);
  EXPECT_NEAR(b.misaligned[0].shifts[0].norm(), 6.0, 1.0);
  for (int t = 0; t < 3; ++t) {
    const Eigen::Vector3d moved = SliceCentre(b, shifted.volume, t, 6);
    EXPECT_LT((moved - SliceCentre(a, straight.volume, t, 6)).norm(), 0.5)
        << "frame " << t;
    // The unshifted neighbours stay where they were.
    EXPECT_LT((SliceCentre(b, shifted.volume, t, 5) -
               SliceCentre(a, straight.volume, t, 5))
                  .norm(),
              1e-9);
  }
  EXPECT_NE(b.warnings[0].find("moved back onto that line"), std::string::npos);
}

TEST(MaskContoursTest, NoLvLabelIsAnError) {
  LabelMap labels;
  labels.lv = 7;
  try {
    ExtractMaskContours(Phantom().volume, labels);
    FAIL();
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(),
                 "mask phantom: no voxel labelled lv=7 (the LV cavity); "
                 "--labels says which value is which (e.g. --labels acdc, "
                 "mnms or lv=3,myo=2,rv=1)");
  }
}

// The stack upside down (apex at the last slice) reads the same.
TEST(MaskContoursTest, StackEitherWayUp) {
  LabelVolume flipped = Phantom().volume;
  const LabelVolume& v = Phantom().volume;
  for (int t = 0; t < v.nt; ++t) {
    for (int k = 0; k < v.nz; ++k) {
      for (int j = 0; j < v.ny; ++j) {
        for (int i = 0; i < v.nx; ++i) {
          flipped.labels[flipped.Index(i, j, v.nz - 1 - k, t)] =
              v.At(i, j, k, t);
        }
      }
    }
  }
  flipped.world_from_voxel.col(3) += v.world_from_voxel.col(2) * (v.nz - 1);
  flipped.world_from_voxel.col(2) *= -1.0;
  const MaskContours a = ExtractMaskContours(v, LabelMap());
  const MaskContours b = ExtractMaskContours(flipped, LabelMap());
  EXPECT_EQ(b.apex_slice, v.nz - 1);
  EXPECT_EQ(b.base_slice[0], v.nz - 1 - a.base_slice[0]);
  EXPECT_EQ(a.points.frames[0].points.size(), b.points.frames[0].points.size());
}

// Slice k of a 48 x 48 stack (2 mm voxels, 8 mm slices): a cavity disk of
// `cavity` voxels' radius, the myocardium out to 10 voxels except over
// longitudes from `open_from` to 180 degrees (none: -180).
void Ring(double cavity, double open_from, int k, LabelVolume* volume) {
  for (int j = 0; j < volume->ny; ++j) {
    for (int i = 0; i < volume->nx; ++i) {
      const double x = i - 23.5, y = j - 23.5, r = std::hypot(x, y);
      const double longitude = std::atan2(y, x) * kDeg;
      std::int32_t label = 0;
      if (r <= cavity) {
        label = 3;
      } else if (r <= 10.0 && longitude < open_from) {
        label = 2;
      }
      volume->labels[volume->Index(i, j, k, 0)] = label;
    }
  }
}

// Above the last closed ring, a slice whose myocardium borders three
// quarters of its cavity is kept as a partial ring, its walls only where
// they border the myocardium; one bordered over a third is not.
TEST(MaskContoursTest, PartialBasalRingKeepsItsBorderedWalls) {
  LabelVolume volume;
  volume.source = "rings";
  volume.nx = volume.ny = 48;
  volume.nz = 6;
  volume.nt = 1;
  volume.labels.assign(48 * 48 * 6, 0);
  volume.world_from_voxel.diagonal() << 2.0, 2.0, 8.0, 1.0;
  Ring(3.0, 180.0, 0, &volume);  // The apex: a small cavity.
  for (int k = 1; k <= 3; ++k) Ring(7.0, 180.0, k, &volume);
  Ring(7.0, 90.0, 4, &volume);   // Open over 90 degrees: 3/4 bordered.
  Ring(7.0, -60.0, 5, &volume);  // Open over 240 degrees.
  const MaskContours c = ExtractMaskContours(volume, LabelMap());
  EXPECT_EQ(c.apex_slice, 0);
  EXPECT_FALSE(c.rings[4].closed);
  EXPECT_NEAR(c.rings[4].myocardial_cover, 0.75, 0.06);
  EXPECT_TRUE(c.rings[4].kept && c.rings[4].partial);
  EXPECT_FALSE(c.rings[5].kept);
  ASSERT_EQ(c.base_slice, (std::vector<int>{4}));
  int endo = 0, epi = 0, opening_middle = 0;
  for (const DataPoint& p : c.points.frames[0].points) {
    if (std::abs(p.position.z() - 32.0) > 1e-9) continue;  // Slice 4.
    const double x = p.position.x() / 2.0 - 23.5;
    const double y = p.position.y() / 2.0 - 23.5;
    const double longitude = std::atan2(y, x) * kDeg;
    // None inside the opening (90 to 180 degrees), but at its edges.
    EXPECT_TRUE(longitude < 90.0 + 12.0 || longitude > 180.0 - 12.0)
        << longitude;
    opening_middle += std::abs(longitude - 135.0) < 30.0;
    (p.layer == WallLayer::kEndocardium ? endo : epi) += 1;
  }
  EXPECT_EQ(opening_middle, 0);
  EXPECT_GT(endo, 20);
  EXPECT_GT(epi, 30);
  // The partial base has no basal face: nothing above slice 4's plane.
  for (const DataPoint& p : c.points.frames[0].points) {
    EXPECT_LE(p.position.z(), 32.0 + 1e-9);
  }
}

}  // namespace
}  // namespace pfdm
