// VTK XML polydata (.vtp), as pfdm writes its frames and ParaView saves
// them uncompressed.
#ifndef PFDM_IO_VTK_XML_READER_H_
#define PFDM_IO_VTK_XML_READER_H_

#include <string>

#include "pfdm/io/legacy_vtk_reader.h"

namespace pfdm {

// A PolyData file's points, its Polys (fanned) and its one-component point
// arrays by name, whatever their numeric types (Float32/64, [U]Int8-64),
// with arrays inline in ASCII or appended raw (header UInt32 or UInt64,
// either byte order).  Verts, lines, strips, cell data and arrays of several
// components are read past.  Base64 ("binary") and compressed arrays are
// refused: ParaView writes those only when asked.  Throws InputError
// "PATH: ...".
VtkMesh ReadVtkXmlPolyData(const std::string& path);

}  // namespace pfdm

#endif  // PFDM_IO_VTK_XML_READER_H_
