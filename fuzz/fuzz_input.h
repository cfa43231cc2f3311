// The fuzzed bytes as a file: pfdm's readers take paths.
#ifndef PFDM_FUZZ_FUZZ_INPUT_H_
#define PFDM_FUZZ_FUZZ_INPUT_H_

#include <sys/stat.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>

namespace pfdm {

// Writes data to a file private to this process (in $TMPDIR, or /tmp) and
// returns its path; named `name` so that readers that go by the name (a
// GPFile_*.txt) take it as they would a real one.
inline std::string FuzzFile(const uint8_t* data, size_t size,
                            const std::string& name) {
  static const std::string dir = [] {
    const char* tmp = std::getenv("TMPDIR");
    std::string path = std::string(tmp != nullptr ? tmp : "/tmp") +
                       "/pfdm_fuzz_" + std::to_string(getpid());
    ::mkdir(path.c_str(), 0700);
    return path;
  }();
  const std::string path = dir + "/" + name;
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data),
             static_cast<std::streamsize>(size));
  return path;
}

}  // namespace pfdm

#endif  // PFDM_FUZZ_FUZZ_INPUT_H_
