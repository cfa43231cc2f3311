#include "pfdm/report/gnuplot.h"

#include <spawn.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <sstream>

#include "pfdm/util/atomic_file.h"
#include "pfdm/util/error.h"

extern char** environ;

namespace pfdm {
namespace {

// An anonymous in-memory file, closed when it goes out of scope: gnuplot's
// script, output and error stream live in these rather than in temporary
// files, so nothing is left behind by a kill and no path is involved.
class MemoryFile {
 public:
  explicit MemoryFile(const std::string& what)
      : fd_(memfd_create("pfdm_gnuplot", MFD_CLOEXEC)) {
    if (fd_ < 0) {
      throw InputError(what + ": gnuplot failed: " + std::strerror(errno));
    }
  }
  ~MemoryFile() { close(fd_); }
  MemoryFile(const MemoryFile&) = delete;
  MemoryFile& operator=(const MemoryFile&) = delete;

  int fd() const { return fd_; }

  bool Write(const std::string& text) {
    size_t done = 0;
    while (done < text.size()) {
      const ssize_t n = write(fd_, text.data() + done, text.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return false;
      done += static_cast<size_t>(n);
    }
    return lseek(fd_, 0, SEEK_SET) == 0;
  }

  std::string Read() const {
    std::string text;
    char buffer[65536];
    off_t offset = 0;
    for (;;) {
      const ssize_t n = pread(fd_, buffer, sizeof(buffer), offset);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      text.append(buffer, static_cast<size_t>(n));
      offset += n;
    }
    return text;
  }

 private:
  int fd_;
};

// gnuplot's message is its last non-blank line ("line 3: all points y value
// undefined!"); the lines before it echo the script.
std::string LastLine(const std::string& text) {
  std::istringstream in(text);
  std::string line, last;
  while (std::getline(in, line)) {
    const size_t start = line.find_first_not_of(" \t\r");
    if (start != std::string::npos) last = line.substr(start);
  }
  if (last.size() > 200) last = last.substr(0, 200) + "...";
  return last;
}

}  // namespace

std::string RenderSvgString(const std::string& what,
                            const std::vector<PlotData>& data,
                            const std::string& script, int width, int height) {
  std::ostringstream full;
  full.precision(10);
  for (const PlotData& block : data) {
    full << '$' << block.name << " << EOD\n";
    for (const auto& row : block.rows) {
      for (size_t i = 0; i < row.size(); ++i) full << (i ? " " : "") << row[i];
      full << '\n';
    }
    full << "EOD\n";
  }
  full << "set terminal svg size " << width << ',' << height
       << " dynamic enhanced font 'sans,12' background rgb 'white'\n"
       << script << "\nunset output\n";

  MemoryFile input(what), output(what), errors(what);
  if (!input.Write(full.str())) {
    throw InputError(what + ": gnuplot failed: cannot buffer the script");
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, input.fd(), 0);
  posix_spawn_file_actions_adddup2(&actions, output.fd(), 1);
  posix_spawn_file_actions_adddup2(&actions, errors.fd(), 2);
  char program[] = "gnuplot";
  char* argv[] = {program, nullptr};
  pid_t pid = 0;
  const int spawned =
      posix_spawnp(&pid, program, &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) {
    throw InputError(what + ": gnuplot failed: " + std::strerror(spawned) +
                     " (is gnuplot-nox installed?)");
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  std::string svg = output.Read();
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 ||
      svg.find("</svg>") == std::string::npos) {
    const std::string message = LastLine(errors.Read());
    throw InputError(
        what + ": gnuplot failed" +
        (message.empty() ? std::string(" with no message") : ": " + message));
  }
  return svg;
}

void RenderSvg(const std::vector<PlotData>& data, const std::string& script,
               const std::string& svg_path, int width, int height) {
  WriteFileAtomically(svg_path,
                      RenderSvgString(svg_path, data, script, width, height));
}

}  // namespace pfdm
