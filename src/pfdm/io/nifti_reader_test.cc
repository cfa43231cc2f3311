#include "pfdm/io/nifti_reader.h"

#include <cstring>

#include "gtest/gtest.h"
#include "nifti2_io.h"
#include "pfdm/io/nifti_writer.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

// A file made with libnifti directly (not pfdm's writer): nx x ny x nz
// voxels of `type`, all 0 but voxel (2, 3, 1) = value; the geometry set
// by `setup`.
void WriteRaw(const std::string& file, int nx, int ny, int nz, int type,
              double value, const std::function<void(nifti_image*)>& setup) {
  const int64_t dims[8] = {nz > 1 ? 3 : 2, nx, ny, nz, 1, 1, 1, 1};
  nifti_image* image = nifti_make_new_nim(dims, type, 1);
  ASSERT_NE(image, nullptr);
  const int64_t n = 2 + nx * (3 + ny * (nz > 1 ? 1 : 0));
  if (type == DT_FLOAT32) static_cast<float*>(image->data)[n] = value;
  if (type == DT_UINT8) static_cast<std::uint8_t*>(image->data)[n] = value;
  if (type == DT_INT16) {
    for (int64_t v = 0; v < image->nvox; ++v) {
      static_cast<std::int16_t*>(image->data)[v] = v % 300;
    }
  }
  setup(image);
  ASSERT_EQ(nifti_set_filenames(image, file.c_str(), 0, 1), 0);
  nifti_image_write(image);
  nifti_image_free(image);
}

// qform: 90 degrees about z (quaternion b, c, d = 0, 0, sin 45), voxels
// 1.25 x 1.5 x 8 mm, offset (10, -20, 30): voxel (2, 3, 1) at R (2.5,
// 4.5, 8) + offset = (-4.5, 2.5, 8) + offset, worked out by hand; qfac -1
// flips k.
void SetQform(nifti_image* image, double qfac) {
  image->qform_code = NIFTI_XFORM_SCANNER_ANAT;
  image->quatern_b = image->quatern_c = 0.0;
  image->quatern_d = std::sqrt(0.5);
  image->qoffset_x = 10;
  image->qoffset_y = -20;
  image->qoffset_z = 30;
  image->qfac = qfac;
  image->pixdim[0] = qfac;
  image->dx = image->pixdim[1] = 1.25;
  image->dy = image->pixdim[2] = 1.5;
  image->dz = image->pixdim[3] = 8.0;
}

TEST(NiftiReaderTest, QformOrientationByHand) {
  const std::string dir = ScratchDirectory("qform");
  for (double qfac : {1.0, -1.0}) {
    const std::string file = dir + (qfac > 0 ? "/plus.nii" : "/minus.nii.gz");
    WriteRaw(file, 6, 5, 4, DT_UINT8, 3,
             [&](nifti_image* image) { SetQform(image, qfac); });
    const LabelVolume v = ReadLabelVolume(file);
    EXPECT_EQ(v.geometry, "qform");
    ASSERT_EQ(v.nx * v.ny * v.nz * v.nt, 120);
    EXPECT_EQ(v.At(2, 3, 1, 0), 3);
    const Eigen::Vector3d expected(5.5, -17.5, qfac > 0 ? 38.0 : 22.0);
    EXPECT_LT((v.World(2, 3, 1) - expected).norm(), 1e-5) << qfac;
    EXPECT_NEAR(v.Spacing(2), 8.0, 1e-6);
    EXPECT_NEAR(v.VoxelVolumeMl(), 0.015, 1e-9);
  }
}

// The sform wins over the qform, row by row as written.
TEST(NiftiReaderTest, SformBeforeQform) {
  const std::string file = ScratchDirectory("sform") + "/s.nii";
  WriteRaw(file, 6, 5, 4, DT_UINT8, 3, [](nifti_image* image) {
    SetQform(image, 1.0);
    image->sform_code = NIFTI_XFORM_ALIGNED_ANAT;
    const double rows[3][4] = {
        {0, 0, 9, -5}, {-1.4, 0, 0, 7}, {0, 1.2, 0.5, 100}};
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 4; ++c) image->sto_xyz.m[r][c] = rows[r][c];
    }
  });
  const LabelVolume v = ReadLabelVolume(file);
  EXPECT_EQ(v.geometry, "sform");
  // (2, 3, 1): (9 - 5, -2.8 + 7, 3.6 + 0.5 + 100).
  EXPECT_LT((v.World(2, 3, 1) - Eigen::Vector3d(4, 4.2, 104.1)).norm(), 1e-5);
}

// A folder of one file per frame, name order, only the *_gt files beside
// ACDC's images.
TEST(NiftiReaderTest, AcdcFolder) {
  const std::string dir = ScratchDirectory("acdc");
  for (int frame : {12, 1}) {
    char name[64];
    std::snprintf(name, sizeof(name), "/patient001_frame%02d_gt.nii.gz", frame);
    WriteRaw(dir + name, 6, 5, 4, DT_UINT8, frame,
             [](nifti_image* image) { SetQform(image, 1.0); });
  }
  WriteRaw(dir + "/patient001_frame01.nii.gz", 6, 5, 4, DT_INT16, 0,
           [](nifti_image* image) { SetQform(image, 1.0); });
  const LabelVolume v = ReadLabelVolume(dir);
  EXPECT_EQ(v.nt, 2);
  EXPECT_EQ(v.At(2, 3, 1, 0), 1);
  EXPECT_EQ(v.At(2, 3, 1, 1), 12);
}

TEST(NiftiReaderTest, BadInputOneLine) {
  const std::string dir = ScratchDirectory("bad");
  auto plain = [](nifti_image* image) { SetQform(image, 1.0); };
  WriteRaw(dir + "/float.nii", 6, 5, 4, DT_FLOAT32, 0.5, plain);
  EXPECT_EQ(InputErrorOf([&] { ReadLabelVolume(dir + "/float.nii"); }),
            dir +
                "/float.nii: voxel 50 holds 0.500000, not a label (a whole "
                "number): an image or a probability map, not a "
                "segmentation");
  WriteRaw(dir + "/flat.nii", 6, 5, 1, DT_UINT8, 3, plain);
  EXPECT_EQ(InputErrorOf([&] { ReadLabelVolume(dir + "/flat.nii"); }),
            dir +
                "/flat.nii: a single 2D slice; pfdm needs a stack of "
                "short-axis slices (x, y, slice[, time])");
  WriteRaw(dir + "/image.nii", 6, 5, 4, DT_INT16, 0, plain);
  EXPECT_EQ(InputErrorOf([&] { ReadLabelVolume(dir + "/image.nii"); }),
            dir +
                "/image.nii: more than 64 distinct values: an image, not "
                "a label map");
  WriteText(dir + "/junk.nii", "not a NIfTI header at all\n");
  EXPECT_EQ(InputErrorOf([&] { ReadLabelVolume(dir + "/junk.nii"); }),
            dir + "/junk.nii: not a readable NIfTI file");
  EXPECT_EQ(InputErrorOf([&] { ReadLabelVolume(dir + "/none.nii"); }),
            dir + "/none.nii: no such file");
}

}  // namespace
}  // namespace pfdm
