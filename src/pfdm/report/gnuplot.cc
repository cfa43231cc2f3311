#include "pfdm/report/gnuplot.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <memory>
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

// Where gnuplot finds the script (posix_spawn's dup2 clears close-on-exec
// on it, even when the memory file already has that number).
constexpr int kScriptDescriptor = 3;
constexpr char kScriptPath[] = "/dev/fd/3";

// gnuplot's message is its last non-blank line ("line 3: all points y value
// undefined!", less the script's name); the lines before it echo the
// script.
std::string LastLine(const std::string& text) {
  std::istringstream in(text);
  std::string line, last;
  while (std::getline(in, line)) {
    const size_t start = line.find_first_not_of(" \t\r");
    if (start != std::string::npos) last = line.substr(start);
  }
  const std::string script = std::string("\"") + kScriptPath + "\" ";
  if (last.rfind(script, 0) == 0) last = last.substr(script.size());
  if (last.size() > 200) last = last.substr(0, 200) + "...";
  return last;
}

}  // namespace

// After each plot a marker on standard output, where the SVG goes too, so
// that the output splits into the plots' documents and a failure is pinned
// on the first plot without one.
constexpr char kEndOfPlot[] = "<!-- pfdm: end of plot -->";

struct SvgRendering::Process {
  explicit Process(const std::string& what)
      : input(what), output(what), errors(what) {}
  MemoryFile input, output, errors;
  pid_t pid = 0;
  int status = 0;
};

SvgRendering::SvgRendering(const std::vector<SvgPlot>& plots) {
  for (const SvgPlot& plot : plots) names_.push_back(plot.what);
  if (plots.empty()) return;
  std::ostringstream full;
  full.precision(10);
  for (const SvgPlot& plot : plots) {
    for (const PlotData& block : plot.data) {
      full << '$' << block.name << " << EOD\n";
      for (const auto& row : block.rows) {
        for (size_t i = 0; i < row.size(); ++i) {
          full << (i ? " " : "") << row[i];
        }
        full << '\n';
      }
      full << "EOD\n";
    }
    full << "set terminal svg size " << plot.width << ',' << plot.height
         << " dynamic enhanced font 'sans,12' background rgb 'white'\n"
         << plot.script << "\nunset output\nset print '-'\nprint '"
         << kEndOfPlot << "'\nreset session\n";
  }
  const std::string& what = names_.front();
  auto process = std::make_unique<Process>(what);
  if (!process->input.Write(full.str())) {
    throw InputError(what + ": gnuplot failed: cannot buffer the script");
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  // The script as a file argument, /dev/fd/3: gnuplot reads its standard
  // input one byte per read(2), which for the bull's-eye's polygons was
  // most of the plots' time.  The name is ours; nothing reaches a shell.
  posix_spawn_file_actions_adddup2(&actions, process->input.fd(),
                                   kScriptDescriptor);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, process->output.fd(), 1);
  posix_spawn_file_actions_adddup2(&actions, process->errors.fd(), 2);
  char program[] = "gnuplot";
  char script[sizeof(kScriptPath)];
  std::memcpy(script, kScriptPath, sizeof(kScriptPath));
  char* argv[] = {program, script, nullptr};
  const int spawned =
      posix_spawnp(&process->pid, program, &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) {
    throw InputError(what + ": gnuplot failed: " + std::strerror(spawned) +
                     " (is gnuplot-nox installed?)");
  }
  process_ = std::move(process);
}

SvgRendering::~SvgRendering() { Wait(); }

void SvgRendering::Wait() {
  if (!process_ || process_->pid == 0) return;
  while (waitpid(process_->pid, &process_->status, 0) < 0 && errno == EINTR) {
  }
  process_->pid = 0;
}

std::vector<std::string> SvgRendering::Finish() {
  if (names_.empty()) return {};
  Wait();
  const std::string text = process_->output.Read();
  const std::string marker = std::string(kEndOfPlot) + "\n";
  std::vector<std::string> svgs;
  for (size_t begin = 0; svgs.size() < names_.size();) {
    const size_t end = text.find(marker, begin);
    if (end == std::string::npos) break;
    svgs.push_back(text.substr(begin, end - begin));
    begin = end + marker.size();
  }
  size_t done = 0;
  while (done < svgs.size() && svgs[done].find("</svg>") != std::string::npos) {
    ++done;
  }
  const int status = process_->status;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && done == names_.size()) {
    return svgs;
  }
  const std::string message = LastLine(process_->errors.Read());
  throw InputError(
      names_[std::min(done, names_.size() - 1)] + ": gnuplot failed" +
      (message.empty() ? std::string(" with no message") : ": " + message));
}

std::vector<std::string> RenderSvgStrings(const std::vector<SvgPlot>& plots) {
  return SvgRendering(plots).Finish();
}

std::string RenderSvgString(const SvgPlot& plot) {
  return RenderSvgStrings({plot}).front();
}

std::string RenderSvgString(const std::string& what,
                            const std::vector<PlotData>& data,
                            const std::string& script, int width, int height) {
  return RenderSvgString(SvgPlot{what, data, script, width, height});
}

void RenderSvg(const std::vector<PlotData>& data, const std::string& script,
               const std::string& svg_path, int width, int height) {
  WriteFileAtomically(svg_path,
                      RenderSvgString(svg_path, data, script, width, height));
}

}  // namespace pfdm
