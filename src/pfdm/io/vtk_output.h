// Which VTK files a fit writes for each frame, and how they store numbers.
#ifndef PFDM_IO_VTK_OUTPUT_H_
#define PFDM_IO_VTK_OUTPUT_H_

#include <string>

#include "pfdm/io/vtk_writer.h"

namespace pfdm {

// One file per frame by default: frame_NNN.vtp, which fit.pvd gathers into
// a time series (ParaView's collection reader opens only XML files); the
// legacy .vtk on request, for tools that read only it.
enum class VtkFiles { kVtp, kVtk, kBoth };

struct VtkOutput {
  VtkFiles files = VtkFiles::kVtp;
  VtkFormat format = VtkFormat::kBinary;
  VtkPrecision precision = VtkPrecision::kFloat;

  bool Vtp() const { return files != VtkFiles::kVtk; }
  bool Vtk() const { return files != VtkFiles::kVtp; }
};

// --vtk_format: the files (vtp, vtk or both) and the encoding (binary or
// ascii), either or both, comma-separated ("both,ascii"); what is not named
// is the default (vtp, binary).  --vtk_precision: float or double.  Throws
// InputError naming the flag and its value.
VtkOutput VtkOutputFromNames(const std::string& format,
                             const std::string& precision);

}  // namespace pfdm

#endif  // PFDM_IO_VTK_OUTPUT_H_
