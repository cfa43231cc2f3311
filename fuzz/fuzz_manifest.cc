// libFuzzer harness: ReadManifest, pfdm batch's cohort CSV.
// Any input must end in a result or an InputError, nothing else.
#include <cstddef>
#include <cstdint>

#include "fuzz_input.h"
#include "pfdm/batch/batch_manifest.h"
#include "pfdm/util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = pfdm::FuzzFile(data, size, "cases.csv");
  try {
    pfdm::ReadManifest(path);
  } catch (const pfdm::InputError&) {
  }
  return 0;
}
