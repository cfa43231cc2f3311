#include "pfdm/util/input_file.h"

#include <sys/stat.h>

#include <algorithm>
#include <fstream>

#include "pfdm/util/error.h"

namespace pfdm {

void CheckRegularFile(const std::string& path) {
  struct stat status;
  if (stat(path.c_str(), &status) != 0) {
    throw InputError(path + ": cannot open the file");
  }
  if (S_ISDIR(status.st_mode)) {
    throw InputError(path + ": is a folder, not a file");
  }
  if (!S_ISREG(status.st_mode)) {
    throw InputError(path +
                     ": is not a regular file (a FIFO, socket or "
                     "device?)");
  }
}

std::string ReadInputBytes(const std::string& path) {
  CheckRegularFile(path);
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw InputError(path + ": cannot open the file");
  // One read of the size the file has (a regular file): a stream copy grew
  // its buffer by doubling and then copied the text once more.
  const std::streamoff size = in.tellg();
  in.seekg(0);
  std::string contents(size < 0 ? 0 : static_cast<size_t>(size), '\0');
  if (size < 0 || !in.read(contents.data(), size) || in.peek() != EOF) {
    throw InputError(path + ": cannot read the file (did it change?)");
  }
  return contents;
}

void CheckNoNul(const std::string& path, const std::string& contents) {
  const size_t nul = contents.find('\0');
  if (nul != std::string::npos) {
    const long line =
        1 + std::count(contents.begin(), contents.begin() + nul, '\n');
    throw InputError(path + ":" + std::to_string(line) +
                     ": contains a NUL byte (not a text file?)");
  }
}

std::string ReadInputFile(const std::string& path) {
  std::string contents = ReadInputBytes(path);
  CheckNoNul(path, contents);
  return contents;
}

std::string Clip(const std::string& text, std::size_t max) {
  if (text.size() <= max) return text;
  return text.substr(0, max) + "...";
}

}  // namespace pfdm
