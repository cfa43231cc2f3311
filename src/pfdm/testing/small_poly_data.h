// A small VTK mesh whose numbers test the writers' and readers' digits:
// four points (one needing 17 digits, one tiny), a data vertex, two
// triangles, scalars and a vector array; is_data written as float32, as
// pfdm's frames write it.  The VTK reader tests' fixture.
#ifndef PFDM_TESTING_SMALL_POLY_DATA_H_
#define PFDM_TESTING_SMALL_POLY_DATA_H_

#include "pfdm/io/vtk_writer.h"

namespace pfdm {

inline VtkPolyData SmallPolyData() {
  VtkPolyData data;
  data.points = {
      {0.1, -2.5, 3e-7}, {1.0 / 3, 4, 5}, {-6, 7.25, 8}, {9, 10, -11.125}};
  data.vertices = {3};
  data.triangles = {{0, 1, 2}, {0, 2, 3}};
  data.point_scalars = {{"u", {0.5, -1, 1.0 / 7, 2}},
                        {"is_data", {0, 0, 0, 1}}};
  data.point_vectors = {
      {"residual", {{1, 2, 3}, {4, 5, 6}, {7, 8, 9}, {0, 0, 0}}}};
  data.float32_scalars = {"is_data"};
  return data;
}

}  // namespace pfdm

#endif  // PFDM_TESTING_SMALL_POLY_DATA_H_
