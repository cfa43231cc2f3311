// libFuzzer harness: ReadLegacyVtkPolyData, ASCII legacy VTK polydata.
// Any input must end in a result or an InputError, nothing else.
#include <cstddef>
#include <cstdint>

#include "fuzz_input.h"
#include "pfdm/io/mesh_reader.h"
#include "pfdm/util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = pfdm::FuzzFile(data, size, "mesh.vtk");
  try {
    pfdm::ReadLegacyVtkPolyData(path);
  } catch (const pfdm::InputError&) {
  }
  return 0;
}
