#include "pfdm/util/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include "pfdm/util/error.h"

namespace pfdm {
namespace {

// Streams do not promise to set errno; a stale or zero one would report
// "Success", so fall back to a plain word.
std::string Reason() {
  return errno != 0 ? std::strerror(errno) : "write failed";
}

[[noreturn]] void Fail(const std::string& path, const std::string& temporary) {
  const std::string reason = Reason();
  std::remove(temporary.c_str());
  throw InputError(path + ": cannot write: " + reason);
}

}  // namespace

void WriteFileAtomically(const std::string& path, const std::string& contents) {
  const std::string temporary = path + ".tmp." + std::to_string(getpid());
  errno = 0;
  std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
  if (!out) Fail(path, temporary);
  out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
  out.flush();
  // Some file systems (NFS, a full disk) only report the failure on close.
  out.close();
  if (!out) Fail(path, temporary);
  errno = 0;
  if (std::rename(temporary.c_str(), path.c_str()) != 0) Fail(path, temporary);
}

void EnsureDirectory(const std::string& dir) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error || !std::filesystem::is_directory(dir)) {
    throw InputError(dir + ": cannot create folder: " +
                     (error ? error.message() : "not a folder"));
  }
}

}  // namespace pfdm
