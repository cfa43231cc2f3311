#include "pfdm/io/nifti_writer.h"

#include "Eigen/Geometry"
#include "gtest/gtest.h"
#include "pfdm/io/nifti_reader.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

// pfdm's writer and reader agree: labels, frames and geometry.
TEST(NiftiWriterTest, RoundTrip) {
  LabelVolume v;
  v.nx = 4;
  v.ny = 3;
  v.nz = 2;
  v.nt = 3;
  for (int n = 0; n < 72; ++n) v.labels.push_back(n % 4);
  const Eigen::Matrix3d r =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized())
          .toRotationMatrix();
  v.world_from_voxel.topLeftCorner<3, 3>() << r.col(0) * 1.4, r.col(1) * 1.4,
      r.col(2) * 10.0;
  v.world_from_voxel.topRightCorner<3, 1>() << -50, 20, 7;
  const std::string file = ScratchDirectory("round") + "/v.nii.gz";
  WriteLabelVolume(v, file);
  const LabelVolume back = ReadLabelVolume(file);
  EXPECT_EQ(back.labels, v.labels);
  EXPECT_EQ(back.nt, 3);
  EXPECT_TRUE(back.world_from_voxel.isApprox(v.world_from_voxel, 1e-6));
}

TEST(NiftiWriterTest, UnwritableFolder) {
  LabelVolume v;
  v.nx = v.ny = v.nz = 2;
  v.nt = 1;
  v.labels.assign(8, 1);
  EXPECT_EQ(InputErrorOf([&] { WriteLabelVolume(v, "/nonexistent/v.nii"); }),
            "/nonexistent/v.nii: could not be written");
}

}  // namespace
}  // namespace pfdm
