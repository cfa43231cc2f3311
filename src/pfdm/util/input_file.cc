#include "pfdm/util/input_file.h"

#include <sys/stat.h>

#include <algorithm>
#include <fstream>
#include <sstream>

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

std::string ReadInputFile(const std::string& path) {
  CheckRegularFile(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path + ": cannot read the file");
  std::string contents = text.str();
  const size_t nul = contents.find('\0');
  if (nul != std::string::npos) {
    const long line =
        1 + std::count(contents.begin(), contents.begin() + nul, '\n');
    throw InputError(path + ":" + std::to_string(line) +
                     ": contains a NUL byte (not a text file?)");
  }
  return contents;
}

std::string Clip(const std::string& text, std::size_t max) {
  if (text.size() <= max) return text;
  return text.substr(0, max) + "...";
}

}  // namespace pfdm
