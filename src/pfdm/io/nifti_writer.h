// Label maps written as NIfTI-1 (.nii or .nii.gz): the tests' masks, and a
// segmentation's frames for a viewer.
#ifndef PFDM_IO_NIFTI_WRITER_H_
#define PFDM_IO_NIFTI_WRITER_H_

#include <string>

#include "pfdm/segmentation/label_volume.h"

namespace pfdm {

// Frames [first_frame, first_frame + num_frames) of `volume` as 16-bit
// labels (a 4D file for more than one frame), the geometry as sform and
// qform (scanner-based) when it is a rotation times voxel sizes, sform
// alone otherwise.  Throws InputError when the file cannot be written.
void WriteLabelVolume(const LabelVolume& volume, const std::string& file,
                      int first_frame = 0, int num_frames = -1);

}  // namespace pfdm

#endif  // PFDM_IO_NIFTI_WRITER_H_
