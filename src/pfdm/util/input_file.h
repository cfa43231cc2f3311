// Input files as the readers take them: whole, regular, without NUL bytes.
#ifndef PFDM_UTIL_INPUT_FILE_H_
#define PFDM_UTIL_INPUT_FILE_H_

#include <cstddef>
#include <string>

namespace pfdm {

// The largest coordinate the readers accept, mm.  A heart is a few hundred
// mm across in any scanner frame; beyond this the fit's sums overflow
// (1e155 squared is past double's range) long before anything is learned.
inline constexpr double kMaxCoordinateMm = 1e6;

// Throws InputError("PATH: ...") unless path is a regular file (a folder,
// FIFO or device is refused before it is opened, so a FIFO cannot hang the
// reader).
void CheckRegularFile(const std::string& path);

// The whole of a regular file, as bytes (binary formats).
std::string ReadInputBytes(const std::string& path);

// The whole of a regular text file.  Throws InputError("PATH:LINE: contains
// a NUL byte") for binary data: the readers split lines as C strings, and a
// NUL would silently cut a row short.
std::string ReadInputFile(const std::string& path);

// The same refusal for contents read as bytes that turned out to be text.
void CheckNoNul(const std::string& path, const std::string& contents);

// text, cut to max characters followed by "...", to echo a field in a
// one-line error without echoing megabytes.
std::string Clip(const std::string& text, std::size_t max = 40);

}  // namespace pfdm

#endif  // PFDM_UTIL_INPUT_FILE_H_
