// The mistakes a new user makes with a points file, each refused with what
// to do instead: a mesh given as points, a CSV separated by tabs or
// semicolons, frames numbered from 1 (issue 34).  Checked before reading,
// where libfccp would only say "missing column 'frame'".
#ifndef PFDM_IO_POINT_FILE_MISTAKES_H_
#define PFDM_IO_POINT_FILE_MISTAKES_H_

#include <string>

namespace pfdm {

// Throws InputError when `text`, the content of `path`, is a mesh (VTK,
// VTP, OBJ, PLY) or a table whose header is separated by tabs or
// semicolons.
void CheckIsPointCsv(const std::string& path, const std::string& text);

// Throws InputError when the first frame is 1 (or any other but 0) rather
// than 0, saying so; `first_frame` the least frame number read.
void CheckFramesStartAtZero(const std::string& path, long long first_frame);

}  // namespace pfdm

#endif  // PFDM_IO_POINT_FILE_MISTAKES_H_
