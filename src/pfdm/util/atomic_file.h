// Files written whole or not at all, and never through a link someone else
// planted: every file pfdm writes goes through here.
#ifndef PFDM_UTIL_ATOMIC_FILE_H_
#define PFDM_UTIL_ATOMIC_FILE_H_

#include <functional>
#include <string>

namespace pfdm {

// Writes contents into a new temporary beside path and renames it over
// path, so a reader never sees half a file.  The temporary is
// PATH.tmp.HOST.PID.RANDOM (HOST this machine's name in letters, digits
// and '-'; RANDOM eight letters or digits), created with O_CREAT | O_EXCL |
// O_NOFOLLOW: a file or link already at that name is never opened, let
// alone written through (another name is drawn, 100 at most), and the
// rename replaces a link at path itself, never what it points to.  Then
// removes what killed writes of path left (RemoveAbandonedTemporaries).
// Throws InputError("PATH: cannot write: REASON").
void WriteFileAtomically(const std::string& path, const std::string& contents);

struct AtomicWriteOptions {
  // Draws RANDOM; empty: the system's random numbers.  Tests plant links at
  // the names it gives.
  std::function<std::string()> random_parts;
  // Off where the caller clears the folder's temporaries itself: the
  // listing after each write costs 0.1 ms in a folder of 200 files.
  bool remove_abandoned = true;
};
void WriteFileAtomically(const std::string& path, const std::string& contents,
                         const AtomicWriteOptions& options);

// The temporary's name for path in this process with that RANDOM part.
std::string TemporaryName(const std::string& path,
                          const std::string& random_part);

// Creates path holding contents unless a file, folder or link is there
// already (O_EXCL | O_NOFOLLOW); true if it made it.  Not atomic: for a
// marker, whose presence counts, not its contents.  Throws
// InputError("PATH: cannot write: REASON").
bool CreateFileIfAbsent(const std::string& path, const std::string& contents);

// Throws InputError("DIR: cannot write in this folder: REASON") unless a
// file can be made in dir: makes a temporary of DIR/name, as
// WriteFileAtomically would, and removes it.
void CheckFolderTakesFiles(const std::string& dir, const std::string& name);

// Removes dir's temporaries of the file final_name whose writer has
// certainly stopped: the name says this host made it, no process of that
// PID runs here, and it is a plain file last written over a minute ago.
// A live writer's temporary, on this machine or on another sharing the
// folder (shards of a batch), is never touched; nor is anything that is not
// a plain file.  Best effort: a failure to list or remove is ignored.
void RemoveAbandonedTemporaries(const std::string& dir,
                                const std::string& final_name);

// Creates dir and its parents; throws InputError if that fails.
void EnsureDirectory(const std::string& dir);

}  // namespace pfdm

#endif  // PFDM_UTIL_ATOMIC_FILE_H_
