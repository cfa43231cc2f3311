// libFuzzer harness: ReadObj, Wavefront OBJ meshes.
// Any input must end in a result or an InputError, nothing else.
#include <cstddef>
#include <cstdint>

#include "fuzz_input.h"
#include "pfdm/io/mesh_reader.h"
#include "pfdm/util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = pfdm::FuzzFile(data, size, "mesh.obj");
  try {
    pfdm::ReadObj(path);
  } catch (const pfdm::InputError&) {
  }
  return 0;
}
