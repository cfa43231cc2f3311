#include "pfdm/util/atomic_file.h"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <random>
#include <string>
#include <system_error>
#include <vector>

#include "pfdm/util/error.h"

namespace pfdm {
namespace {

namespace fs = std::filesystem;

// Random names collide by chance once in 62^8 draws; a hundred taken in a
// row means someone fills the names on purpose.
constexpr int kNameAttempts = 100;
// A write takes milliseconds; a temporary untouched for this long, whose
// writer is gone, was left by a kill.  The age guards against two machines
// of one name, whose PIDs this host cannot see.
constexpr std::time_t kAbandonedAfterSeconds = 60;
constexpr int kCreateFlags =
    O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC;

std::string Reason(int error) {
  return error != 0 ? std::strerror(error) : "write failed";
}

// This machine's name as it goes into a file name: the writer's host, so
// that a cleanup on another machine sharing the folder leaves it alone.
const std::string& HostPart() {
  static const std::string host = [] {
    char name[256] = {};
    std::string clean;
    if (gethostname(name, sizeof(name) - 1) == 0) {
      for (const char* c = name; *c != '\0' && clean.size() < 63; ++c) {
        clean += std::isalnum(static_cast<unsigned char>(*c)) ? *c : '-';
      }
    }
    return clean.empty() ? std::string("host") : clean;
  }();
  return host;
}

std::string RandomPart() {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
  unsigned char bytes[8];
  if (getrandom(bytes, sizeof(bytes), 0) != sizeof(bytes)) {
    std::random_device device;
    for (unsigned char& byte : bytes)
      byte = static_cast<unsigned char>(device());
  }
  std::string part;
  for (unsigned char byte : bytes) part += kAlphabet[byte % 62];
  return part;
}

// The prefix of this host's temporaries of final_name: FINAL.tmp.HOST.
std::string HostPrefix(const std::string& final_name) {
  return final_name + ".tmp." + HostPart() + ".";
}

struct Temporary {
  int fd = -1;
  std::string path;
};

// Makes *temporary, a new file beside path under a fresh name; never one
// that was there, a link included.  0, or the errno of the failure (EEXIST:
// every name drawn was taken).
int CreateTemporary(const std::string& path,
                    const std::function<std::string()>& random_parts,
                    Temporary* temporary) {
  for (int attempt = 1;; ++attempt) {
    temporary->path = TemporaryName(path, random_parts());
    temporary->fd = open(temporary->path.c_str(), kCreateFlags, 0666);
    if (temporary->fd >= 0) return 0;
    // EEXIST: something is at the name (O_EXCL also refuses a link there).
    if (errno != EEXIST || attempt == kNameAttempts) return errno;
  }
}

// The reason CreateTemporary failed, for "PATH: cannot write: REASON".
std::string CreateReason(int error, const Temporary& last) {
  if (error != EEXIST) return Reason(error);
  return "the " + std::to_string(kNameAttempts) +
         " temporary names drawn beside it were all taken (" + last.path +
         " and others: planted?)";
}

// Writes all of contents to fd; errno on failure, 0 on success.
int WriteAll(int fd, const std::string& contents) {
  size_t done = 0;
  while (done < contents.size()) {
    const ssize_t n = write(fd, contents.data() + done, contents.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return n < 0 ? errno : EIO;
    done += static_cast<size_t>(n);
  }
  return 0;
}

// Fills and closes a file made by this process; on failure removes it and
// throws InputError("PATH: cannot write: REASON").
void FillAndClose(int fd, const std::string& made, const std::string& path,
                  const std::string& contents) {
  int error = WriteAll(fd, contents);
  // Some file systems (NFS, a full disk) only report the failure on close.
  if (close(fd) != 0 && error == 0) error = errno != 0 ? errno : EIO;
  if (error != 0) {
    unlink(made.c_str());
    throw InputError(path + ": cannot write: " + Reason(error));
  }
}

// Whether the temporary `name` in dir (a temporary of final_name made on
// this host) was left by a writer that has stopped.
bool IsAbandoned(const std::string& dir, const std::string& name,
                 const std::string& final_name) {
  // NAME.tmp.HOST.PID.RANDOM: the PID, then RANDOM with no dot.
  const std::string rest = name.substr(HostPrefix(final_name).size());
  const size_t dot = rest.find('.');
  if (dot == 0 || dot == std::string::npos || dot > 9 ||
      rest.find('.', dot + 1) != std::string::npos || dot + 1 == rest.size()) {
    return false;
  }
  for (size_t i = 0; i < dot; ++i) {
    if (!std::isdigit(static_cast<unsigned char>(rest[i]))) return false;
  }
  const pid_t pid = static_cast<pid_t>(std::stol(rest.substr(0, dot)));
  if (pid <= 0 || pid == getpid()) return false;
  // EPERM: it runs, as another user.
  if (kill(pid, 0) == 0 || errno != ESRCH) return false;
  struct stat status;
  if (lstat((dir + "/" + name).c_str(), &status) != 0 ||
      !S_ISREG(status.st_mode)) {
    return false;
  }
  return std::time(nullptr) - status.st_mtime > kAbandonedAfterSeconds;
}

}  // namespace

std::string TemporaryName(const std::string& path,
                          const std::string& random_part) {
  return HostPrefix(path) + std::to_string(getpid()) + "." + random_part;
}

void WriteFileAtomically(const std::string& path, const std::string& contents) {
  WriteFileAtomically(path, contents, AtomicWriteOptions());
}

void WriteFileAtomically(const std::string& path, const std::string& contents,
                         const AtomicWriteOptions& options) {
  Temporary temporary;
  if (const int error = CreateTemporary(
          path, options.random_parts ? options.random_parts : RandomPart,
          &temporary)) {
    throw InputError(path +
                     ": cannot write: " + CreateReason(error, temporary));
  }
  FillAndClose(temporary.fd, temporary.path, path, contents);
  if (std::rename(temporary.path.c_str(), path.c_str()) != 0) {
    const int error = errno;
    unlink(temporary.path.c_str());
    throw InputError(path + ": cannot write: " + Reason(error));
  }
  if (!options.remove_abandoned) return;
  const fs::path written(path);
  RemoveAbandonedTemporaries(written.has_parent_path()
                                 ? written.parent_path().string()
                                 : std::string("."),
                             written.filename().string());
}

bool CreateFileIfAbsent(const std::string& path, const std::string& contents) {
  const int fd = open(path.c_str(), kCreateFlags, 0666);
  if (fd < 0) {
    if (errno == EEXIST) return false;
    throw InputError(path + ": cannot write: " + Reason(errno));
  }
  FillAndClose(fd, path, path, contents);
  return true;
}

void CheckFolderTakesFiles(const std::string& dir, const std::string& name) {
  Temporary probe;
  if (const int error = CreateTemporary(dir + "/" + name, RandomPart, &probe)) {
    throw InputError(
        dir + ": cannot write in this folder: " + CreateReason(error, probe));
  }
  close(probe.fd);
  unlink(probe.path.c_str());
}

void RemoveAbandonedTemporaries(const std::string& dir,
                                const std::string& final_name) {
  // readdir, not std::filesystem: this runs after every write, and building
  // a path per entry made it 0.3 ms a listing of 200 files.
  DIR* folder = opendir(dir.c_str());
  if (folder == nullptr) return;
  const std::string prefix = HostPrefix(final_name);
  std::vector<std::string> abandoned;
  while (const dirent* entry = readdir(folder)) {
    if (std::strncmp(entry->d_name, prefix.c_str(), prefix.size()) == 0 &&
        IsAbandoned(dir, entry->d_name, final_name)) {
      abandoned.push_back(dir + "/" + entry->d_name);
    }
  }
  closedir(folder);
  for (const std::string& path : abandoned) unlink(path.c_str());
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
