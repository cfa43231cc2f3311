// Files written whole or not at all.
#ifndef PFDM_UTIL_ATOMIC_FILE_H_
#define PFDM_UTIL_ATOMIC_FILE_H_

#include <string>

namespace pfdm {

// Writes PATH.tmp.<pid> beside path and renames it over path, so a reader
// never sees half a file.  Throws InputError("PATH: cannot write: ...").
void WriteFileAtomically(const std::string& path, const std::string& contents);

// WriteFileAtomically in two steps: the contents go to the temporary now,
// the rename waits for Commit, so a set of files can be written while the
// rest of the set is still being made and appear together.  Destroyed
// uncommitted, it removes the temporary.
class StagedFile {
 public:
  // Throws InputError("PATH: cannot write: ...") and leaves nothing.
  StagedFile(std::string path, const std::string& contents);
  StagedFile(StagedFile&& other) noexcept;
  StagedFile& operator=(StagedFile&&) = delete;
  StagedFile(const StagedFile&) = delete;
  ~StagedFile();

  const std::string& path() const { return path_; }
  const std::string& temporary() const { return temporary_; }
  // Renames the temporary onto path; throws InputError as above.
  void Commit();

 private:
  std::string path_;
  std::string temporary_;  // Empty once committed or moved from.
};

// Creates dir and its parents; throws InputError if that fails.
void EnsureDirectory(const std::string& dir);

}  // namespace pfdm

#endif  // PFDM_UTIL_ATOMIC_FILE_H_
