// biv-me patient 1's own LV endocardial meshes (../shared/data) and their
// volumes, measured without a model: the real-data tests' second
// measurement.
#ifndef PFDM_TESTING_BIV_ME_MESHES_H_
#define PFDM_TESTING_BIV_ME_MESHES_H_

#include <cstdio>
#include <string>
#include <vector>

#include "pfdm/io/mesh_reader.h"
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

}  // namespace pfdm

#endif  // PFDM_TESTING_BIV_ME_MESHES_H_
