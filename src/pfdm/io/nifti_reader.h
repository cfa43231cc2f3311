// Label maps from NIfTI-1 or NIfTI-2 files (.nii, .nii.gz), read with
// libnifti2 (docs/segmentation.md says why not ITK).
#ifndef PFDM_IO_NIFTI_READER_H_
#define PFDM_IO_NIFTI_READER_H_

#include <string>

#include "pfdm/segmentation/label_volume.h"

namespace pfdm {

// A 4D file (x, y, slice, time), a 3D file (one frame), or a folder of 3D
// files, one per frame in name order (.nii and .nii.gz; where some names
// hold "_gt", only those: ACDC's patientNNN_frameMM_gt.nii.gz beside its
// images).  World coordinates from the sform, else the qform, else the
// voxel sizes alone.  Throws InputError naming the file: unreadable, not
// 3D or 4D (a single slice), not whole numbers (an image or a probability
// map, not labels), more than 64 distinct values, frames of different grids.
LabelVolume ReadLabelVolume(const std::string& path);

}  // namespace pfdm

#endif  // PFDM_IO_NIFTI_READER_H_
