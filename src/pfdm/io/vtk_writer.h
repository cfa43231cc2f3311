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
  // Scalars kept as float32 at any precision: flags, weights and values for
  // display, whose doubles' last digits say nothing.
  std::vector<std::string> float32_scalars;
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

// How wide a VTK file's real numbers are.  float32 holds a point of a
// heart-sized model to a micrometre or better, and halves the file;
// double keeps every value bit for bit.  Either way float32_scalars are
// float32, and cell indices 32-bit where they fit.
enum class VtkPrecision {
  kFloat,   // Every real array float32.
  kDouble,  // Points, vectors and scalars but float32_scalars as doubles.
};

// "float" or "double"; throws InputError naming --vtk_precision otherwise.
VtkPrecision VtkPrecisionFromName(const std::string& name);

// Whether the array of that name is written as float32.
bool IsFloat32Array(const VtkPolyData& data, const std::string& name,
                    VtkPrecision precision);

std::string ToLegacyVtk(const VtkPolyData& data, const std::string& title,
                        VtkFormat format = VtkFormat::kAscii,
                        VtkPrecision precision = VtkPrecision::kDouble);

// Appends value as printf's %.9g would (a nanometre on a heart-sized model;
// ParaView reads any precision) and an int in decimal, without a stream:
// formatting through std::ostream was most of the time of writing outputs.
void AppendVtkNumber(double value, std::string* out);
void AppendVtkNumber(int value, std::string* out);
// A float as the shortest decimal that reads back as the same float.
void AppendVtkNumber(float value, std::string* out);

}  // namespace pfdm

#endif  // PFDM_IO_VTK_WRITER_H_
