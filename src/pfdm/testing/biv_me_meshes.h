// biv-me patient 1's own LV endocardial meshes (../shared/data) and what
// they measure without a model: the real-data tests' second measurement.
#ifndef PFDM_TESTING_BIV_ME_MESHES_H_
#define PFDM_TESTING_BIV_ME_MESHES_H_

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "Eigen/Core"
#include "pfdm/io/mesh_reader.h"
#include "pfdm/model/base_plane.h"
#include "pfdm/util/triangle_mesh.h"

namespace pfdm {

// The 25 frames' meshes under `shared` (SharedDataDirectory()).
inline std::vector<TriangleMesh> BivMeLvMeshes(const std::string& shared) {
  std::vector<TriangleMesh> meshes;
  for (int t = 0; t < 25; ++t) {
    char name[64];
    std::snprintf(name, sizeof(name), "/obj/patient1_LV_ENDOCARDIAL_%03d.obj",
                  t);
    meshes.push_back(ReadObj(shared + "/biv-me-patient1" + name));
  }
  return meshes;
}

// Each mesh's volume closed across its open rim, ml.
inline std::vector<double> MeshVolumes(
    const std::vector<TriangleMesh>& meshes) {
  std::vector<double> volumes;
  for (const auto& mesh : meshes) {
    volumes.push_back(EnclosedVolume(CapBoundaryLoops(mesh)) / 1000.0);
  }
  return volumes;
}

// Each mesh's length from its mitral valve plane to its farthest point (the
// apex), mm: the long axis's length measured without the model.
inline std::vector<double> MeshLengths(const std::vector<TriangleMesh>& meshes,
                                       const std::vector<BasePlane>& planes) {
  std::vector<double> lengths;
  for (size_t t = 0; t < meshes.size(); ++t) {
    double length = 0.0;
    for (const Eigen::Vector3d& x : meshes[t].points) {
      length = std::max(length,
                        std::abs((x - planes[t].point).dot(planes[t].normal)));
    }
    lengths.push_back(length);
  }
  return lengths;
}

}  // namespace pfdm

#endif  // PFDM_TESTING_BIV_ME_MESHES_H_
