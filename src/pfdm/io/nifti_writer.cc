#include "pfdm/io/nifti_writer.h"

#include <cstdint>
#include <cstring>
#include <filesystem>

#include "nifti2_io.h"
#include "pfdm/util/error.h"

namespace pfdm {

namespace {

nifti_dmat44 ToDmat(const Eigen::Matrix4d& m) {
  nifti_dmat44 out;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) out.m[r][c] = m(r, c);
  }
  return out;
}

void SetGeometry(const Eigen::Matrix4d& m, nifti_image* image) {
  image->sform_code = NIFTI_XFORM_SCANNER_ANAT;
  image->sto_xyz = ToDmat(m);
  image->sto_ijk = nifti_dmat44_inverse(image->sto_xyz);
  image->dx = image->pixdim[1] = m.col(0).head<3>().norm();
  image->dy = image->pixdim[2] = m.col(1).head<3>().norm();
  image->dz = image->pixdim[3] = m.col(2).head<3>().norm();
  Eigen::Matrix3d r = m.topLeftCorner<3, 3>();
  for (int c = 0; c < 3; ++c) r.col(c) /= r.col(c).norm();
  if ((r.transpose() * r - Eigen::Matrix3d::Identity()).norm() > 1e-6) {
    return;  // Sheared: no quaternion says it.
  }
  image->qform_code = NIFTI_XFORM_SCANNER_ANAT;
  double qfac = 1.0;
  nifti_dmat44_to_quatern(image->sto_xyz, &image->quatern_b, &image->quatern_c,
                          &image->quatern_d, &image->qoffset_x,
                          &image->qoffset_y, &image->qoffset_z, nullptr,
                          nullptr, nullptr, &qfac);
  image->qfac = qfac;
  image->qto_xyz = image->sto_xyz;
  image->qto_ijk = image->sto_ijk;
}

}  // namespace

void WriteLabelVolume(const LabelVolume& volume, const std::string& file,
                      int first_frame, int num_frames) {
  if (num_frames < 0) num_frames = volume.nt - first_frame;
  const int64_t dims[8] = {num_frames > 1 ? 4 : 3,
                           volume.nx,
                           volume.ny,
                           volume.nz,
                           num_frames,
                           1,
                           1,
                           1};
  nifti_set_debug_level(0);  // Its messages would not be one line.
  nifti_image* image = nifti_make_new_nim(dims, DT_INT16, 1);
  if (image == nullptr) throw InputError(file + ": cannot make the image");
  auto* data = static_cast<std::int16_t*>(image->data);
  const size_t per_frame =
      static_cast<size_t>(volume.nx) * volume.ny * volume.nz;
  for (size_t n = 0; n < per_frame * num_frames; ++n) {
    data[n] =
        static_cast<std::int16_t>(volume.labels[per_frame * first_frame + n]);
  }
  SetGeometry(volume.world_from_voxel, image);
  const int failed = nifti_set_filenames(image, file.c_str(), 0, 1);
  if (!failed) nifti_image_write(image);
  nifti_image_free(image);
  if (failed) throw InputError(file + ": not a NIfTI file name");
  if (!std::filesystem::is_regular_file(file)) {
    throw InputError(file + ": could not be written");
  }
}

}  // namespace pfdm
