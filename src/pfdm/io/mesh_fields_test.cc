#include "pfdm/io/mesh_fields.h"

#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

TEST(MeshFieldsTest, NumbersCoordinatesAndIntegersAreCheckedWhole) {
  EXPECT_EQ(ToNumber("f:1", "-2.5e-3"), -2.5e-3);
  EXPECT_EQ(InputErrorOf([] { ToNumber("f:1", "1.5x"); }),
            "f:1: '1.5x' is not a number");
  EXPECT_EQ(InputErrorOf([] { ToNumber("f:2", "inf"); }),
            "f:2: not a finite number");
  EXPECT_EQ(ToCoordinate("f:1", "-1e6"), -1e6);
  EXPECT_EQ(InputErrorOf([] { ToCoordinate("f:3", "1.5e6"); }),
            "f:3: coordinate '1.5e6' is out of range (more than 1e6 mm from "
            "the origin)");
  EXPECT_EQ(ToInteger("f:1", "-12"), -12);
  EXPECT_EQ(InputErrorOf([] { ToInteger("f:4", "3.0"); }),
            "f:4: '3.0' is not an integer");
  EXPECT_EQ(InputErrorOf([] { ToInteger("f:5", ""); }),
            "f:5: '' is not an integer");
}

TEST(MeshFieldsTest, PolygonsAreFannedAndTheirIndicesChecked) {
  TriangleMesh mesh;
  AddFan("f:1", {4, 1, 2, 3}, 5, &mesh);
  EXPECT_EQ(mesh.triangles,
            (std::vector<std::array<int, 3>>{{4, 1, 2}, {4, 2, 3}}));
  EXPECT_EQ(InputErrorOf([&] {
              AddFan("f:2", {0, 1, 5}, 5, &mesh);
            }),
            "f:2: vertex 5 out of range");
  EXPECT_EQ(InputErrorOf([&] {
              AddFan("f:3", {0, -1, 2}, 5, &mesh);
            }),
            "f:3: vertex -1 out of range");
  EXPECT_EQ(mesh.triangles.size(), 2u);  // Nothing added on an error.
}

}  // namespace
}  // namespace pfdm
