// Legacy VTK polydata, which ParaView opens, and how VTK files store numbers.
#ifndef PFDM_IO_VTK_WRITER_H_
#define PFDM_IO_VTK_WRITER_H_

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "Eigen/Core"

namespace pfdm {

struct VtkPolyData {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> vertices;  // Points emitted as VERTICES cells.
  std::vector<std::pair<std::string, std::vector<double>>> point_scalars;
  std::vector<std::pair<std::string, std::vector<Eigen::Vector3d>>>
      point_vectors;
};

// How a VTK file stores its arrays.  Binary needs no number formatting,
// which made up most of the time of writing outputs, and keeps every double
// exactly; ParaView, VTK and meshio read both.
enum class VtkFormat {
  kAscii,   // Decimal text, 9 significant digits.
  kBinary,  // Legacy: BINARY (big-endian); XML: appended raw.
};

// "ascii" or "binary"; throws InputError naming --vtk_format otherwise.
VtkFormat VtkFormatFromName(const std::string& name);

std::string ToLegacyVtk(const VtkPolyData& data, const std::string& title,
                        VtkFormat format = VtkFormat::kAscii);

// Appends value as printf's %.9g would (a nanometre on a heart-sized model;
// ParaView reads any precision) and an int in decimal, without a stream:
// formatting through std::ostream was most of the time of writing outputs.
void AppendVtkNumber(double value, std::string* out);
void AppendVtkNumber(int value, std::string* out);

}  // namespace pfdm

#endif  // PFDM_IO_VTK_WRITER_H_
