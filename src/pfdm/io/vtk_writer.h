// Legacy ASCII VTK polydata, which ParaView opens.
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

std::string ToLegacyVtk(const VtkPolyData& data, const std::string& title);

// Appends value as printf's %.9g would (a nanometre on a heart-sized model;
// ParaView reads any precision) and an int in decimal, without a stream:
// formatting through std::ostream was most of the time of writing outputs.
void AppendVtkNumber(double value, std::string* out);
void AppendVtkNumber(int value, std::string* out);

}  // namespace pfdm

#endif  // PFDM_IO_VTK_WRITER_H_
