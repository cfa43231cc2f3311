// Files written whole or not at all.
#ifndef PFDM_UTIL_ATOMIC_FILE_H_
#define PFDM_UTIL_ATOMIC_FILE_H_

#include <string>

namespace pfdm {

// Writes PATH.tmp.<pid> beside path and renames it over path, so a reader
// never sees half a file.  Throws InputError("PATH: cannot write: ...").
void WriteFileAtomically(const std::string& path, const std::string& contents);

// Creates dir and its parents; throws InputError if that fails.
void EnsureDirectory(const std::string& dir);

}  // namespace pfdm

#endif  // PFDM_UTIL_ATOMIC_FILE_H_
