// biv-me guide-point files with or without their header line.
#ifndef PFDM_IO_GP_FILE_HEADER_H_
#define PFDM_IO_GP_FILE_HEADER_H_

#include <string>

namespace pfdm {

// A GPFile's text ready for a reader that wants a header line.  The first
// non-blank line is the header unless its first field is a number: then the
// file has none (biv-me writes some so, its second test case among them, and
// reads every file headerless, dropping the first row), and the text comes
// back behind the header biv-me's column order gives, `x y z contour type
// frameID weight time frame`, as many of those as that row has fields
// (further ones named "column N"), with *headerless set.  Its data lines are
// then one line further down than in the file.  Throws InputError
// "FILE:LINE: a GPFile row without a header line needs x, y, z and contour
// type (biv-me's column order), got N fields".
std::string WithGpFileHeader(const std::string& file, const std::string& text,
                             bool* headerless);

}  // namespace pfdm

#endif  // PFDM_IO_GP_FILE_HEADER_H_
