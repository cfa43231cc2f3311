// VTK XML polydata (.vtp) and ParaView collections (.pvd): ParaView's PVD
// reader only opens XML files, so a time series needs .vtp frames.
#ifndef PFDM_IO_VTP_WRITER_H_
#define PFDM_IO_VTP_WRITER_H_

#include <string>
#include <utility>
#include <vector>

#include "pfdm/io/vtk_writer.h"

namespace pfdm {

// The same content as ToLegacyVtk, as VTK XML PolyData.  Binary: every
// array appended raw after the XML (<AppendedData encoding="raw">, each
// block a UInt64 byte count and the values in the machine's byte order,
// which the header names), of the same types as in ASCII: reals Float32 or
// Float64 as precision says (IsFloat32Array), indices Int32 where they fit.
std::string ToVtkXmlPolyData(const VtkPolyData& data,
                             VtkFormat format = VtkFormat::kAscii,
                             VtkPrecision precision = VtkPrecision::kDouble);

// A collection of (time, file) pairs, files relative to the .pvd's folder.
std::string PvdCollection(
    const std::vector<std::pair<double, std::string>>& timesteps);

}  // namespace pfdm

#endif  // PFDM_IO_VTP_WRITER_H_
