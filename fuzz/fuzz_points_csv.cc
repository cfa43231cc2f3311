// libFuzzer harness: ReadPointsCsv, pfdm's frame,id,x,y,z CSV.
// Any input must end in a result or an InputError, nothing else.
#include <cstddef>
#include <cstdint>

#include "fuzz_input.h"
#include "pfdm/io/point_reader.h"
#include "pfdm/util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = pfdm::FuzzFile(data, size, "points.csv");
  try {
    pfdm::ReadPointsCsv(path);
  } catch (const pfdm::InputError&) {
  }
  return 0;
}
