// libFuzzer harness: ReadLegacyVtkPolyData, legacy VTK polydata (ASCII or
// binary).
// Any input must end in a result or an InputError, nothing else.
#include <cstddef>
#include <cstdint>

#include "fuzz_input.h"
#include "pfdm/io/legacy_vtk_reader.h"
#include "pfdm/util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = pfdm::FuzzFile(data, size, "mesh.vtk");
  try {
    pfdm::ReadLegacyVtkPolyData(path);
  } catch (const pfdm::InputError&) {
  }
  return 0;
}
