#include "pfdm/batch/case_folder.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "pfdm/io/fit_output.h"
#include "pfdm/util/atomic_file.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

namespace fs = std::filesystem;

// Reads the plain file path into *contents, never through a link; false if
// nothing is there.  Throws InputError("PATH: ...") for anything else: a
// link planted there could show another file's contents in the summary.
bool ReadPlainFile(const std::string& path, std::string* contents) {
  const int fd =
      open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) {
    if (errno == ENOENT) return false;
    throw InputError(
        path + (errno == ELOOP
                    ? std::string(": is a link, not a file "
                                  "pfdm wrote")
                    : ": cannot open: " + std::string(std::strerror(errno))));
  }
  struct stat status;
  if (fstat(fd, &status) != 0 || !S_ISREG(status.st_mode)) {
    close(fd);
    throw InputError(path + ": is not a plain file");
  }
  contents->clear();
  char buffer[65536];
  for (;;) {
    const ssize_t n = read(fd, buffer, sizeof(buffer));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int error = errno;
      close(fd);
      throw InputError(path + ": cannot read: " + std::strerror(error));
    }
    if (n == 0) break;
    contents->append(buffer, static_cast<size_t>(n));
  }
  close(fd);
  return true;
}

// Why the folder dir (a real folder, not a link) is not pfdm's, or "".
std::string FolderRefusal(const std::string& dir) {
  const std::string marker = dir + "/" + kOutputMarker;
  std::error_code error;
  const fs::file_status status = fs::symlink_status(marker, error);
  if (fs::is_regular_file(status)) return "";
  if (fs::exists(status)) {
    return marker + ": is not a plain file, so " + dir +
           " is not a case folder of pfdm's; pfdm batch leaves it alone";
  }
  const bool empty = fs::is_empty(dir, error);
  if (error) return dir + ": cannot list the folder: " + error.message();
  if (empty) return "";
  return dir + ": holds files pfdm did not mark as its own (no " +
         kOutputMarker +
         "); pfdm batch leaves it alone: move them, or create that file "
         "if an older pfdm wrote them";
}

}  // namespace

std::string CaseFolderRefusal(const std::string& dir) {
  std::error_code error;
  const fs::file_status status = fs::symlink_status(dir, error);
  if (!fs::exists(status)) {
    return error && error != std::errc::no_such_file_or_directory
               ? dir + ": cannot look at the case folder: " + error.message()
               : "";
  }
  if (fs::is_symlink(status)) {
    return dir +
           ": is a link, not a case folder of pfdm's; pfdm batch does not "
           "write through it";
  }
  if (!fs::is_directory(status)) {
    return dir + ": is a file, not a case folder; pfdm batch leaves it alone";
  }
  return FolderRefusal(dir);
}

void ClaimCaseFolder(const std::string& dir) {
  // mkdir, not create_directories: that would make the folders of a path
  // through a link.
  if (mkdir(dir.c_str(), 0777) != 0 && errno != EEXIST) {
    throw InputError(dir + ": cannot create folder: " + std::strerror(errno));
  }
  const std::string refusal = CaseFolderRefusal(dir);
  if (!refusal.empty()) throw InputError(refusal);
  CreateFileIfAbsent(dir + "/" + kOutputMarker, kOutputMarkerText);
}

CaseSummary CaseStatus(const std::string& dir, const std::string& name) {
  CaseSummary summary;
  summary.name = name;
  summary.status = "failed";
  summary.error = CaseFolderRefusal(dir);
  if (!summary.error.empty()) return summary;
  try {
    std::string text;
    // fit.json, written last, marks a complete set.
    if (ReadPlainFile(dir + "/fit.json", &text)) {
      return SummaryFromFitJson(name, text, dir + "/fit.json");
    }
    summary.status = "pending";
    if (ReadPlainFile(dir + "/error.txt", &text)) {
      summary.status = "failed";
      while (!text.empty() && text.back() == '\n') text.pop_back();
      summary.error = text;
    }
  } catch (const InputError& error) {
    // One unreadable case must not cost the cohort its summary; it is
    // fitted again by the next run.
    summary = CaseSummary();
    summary.name = name;
    summary.status = "failed";
    summary.error = error.what();
  }
  return summary;
}

}  // namespace pfdm
