#include "pfdm/report/gnuplot.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <memory>
#include <sstream>

#include "glog/logging.h"
#include "pfdm/util/atomic_file.h"
#include "pfdm/util/error.h"

extern char** environ;

namespace pfdm {
namespace {

// fd moved to a number of 10 or more, close-on-exec: the child's
// descriptors 0-4 are then never among the ones it is handed.
int HighDescriptor(int fd) {
  if (fd < 0) return fd;
  const int high = fcntl(fd, F_DUPFD_CLOEXEC, 10);
  close(fd);
  return high;
}

// An anonymous in-memory file, closed when it goes out of scope: gnuplot's
// script, output and error stream live in these rather than in temporary
// files, so nothing is left behind by a kill and no path is involved.
class MemoryFile {
 public:
  explicit MemoryFile(const std::string& what)
      : fd_(HighDescriptor(memfd_create("pfdm_gnuplot", MFD_CLOEXEC))) {
    if (fd_ < 0) {
      throw InputError(what + ": gnuplot failed: " + std::strerror(errno));
    }
  }
  ~MemoryFile() { close(fd_); }
  MemoryFile(const MemoryFile&) = delete;
  MemoryFile& operator=(const MemoryFile&) = delete;

  int fd() const { return fd_; }

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

// Where gnuplot finds the script and writes the SVGs.  Its standard
// output is line buffered, a write(2) per line of SVG (5,000 for the
// report, 7 us each on a VM); a file it opens itself is fully buffered.
constexpr int kScriptDescriptor = 3;
constexpr char kScriptPath[] = "/dev/fd/3";
constexpr int kOutputDescriptor = 4;

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

// Each plot writes one SVG document, whole: the output splits after each
// end tag, and a failure is pinned on the first plot without one.
constexpr char kEndOfSvg[] = "</svg>\n";

// Writes `text` to a pipe; false if that fails (the reader is gone).
// SIGPIPE is held off for this thread meanwhile, so a gnuplot that died
// does not take the caller's process with it.
bool WriteToPipe(int fd, const std::string& text) {
  sigset_t pipe_signal, old_mask, pending;
  sigemptyset(&pipe_signal);
  sigaddset(&pipe_signal, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipe_signal, &old_mask);
  sigpending(&pending);
  const bool was_pending = sigismember(&pending, SIGPIPE) == 1;
  size_t done = 0;
  bool ok = true;
  while (done < text.size()) {
    const ssize_t n = write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      ok = false;
      break;
    }
    done += static_cast<size_t>(n);
  }
  if (!ok && errno == EPIPE && !was_pending) {
    const timespec now{0, 0};
    sigtimedwait(&pipe_signal, nullptr, &now);  // The one this write raised.
  }
  pthread_sigmask(SIG_SETMASK, &old_mask, nullptr);
  return ok;
}

struct SvgRendering::Process {
  explicit Process(const std::string& what) : output(what), errors(what) {}
  ~Process() { CloseScript(); }
  void CloseScript() {
    if (script >= 0) close(script);
    script = -1;
  }
  int script = -1;  // The pipe's writing end; gnuplot reads the other.
  MemoryFile output, errors;
  pid_t pid = 0;
  int status = 0;
};

SvgRendering::SvgRendering() {
  auto process = std::make_unique<Process>("gnuplot");
  int pipe_ends[2];
  if (pipe2(pipe_ends, O_CLOEXEC) != 0) {
    throw InputError(std::string("gnuplot failed: ") + std::strerror(errno));
  }
  for (int& end : pipe_ends) end = HighDescriptor(end);
  process->script = pipe_ends[1];
  // Room for the whole script (best effort): Render then never waits for
  // gnuplot to read.
  fcntl(pipe_ends[1], F_SETPIPE_SZ, 1 << 20);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, process->errors.fd(), 1);
  posix_spawn_file_actions_adddup2(&actions, process->errors.fd(), 2);
  // The script as a file argument, /dev/fd/3: gnuplot reads its standard
  // input one byte per read(2), which for the bull's-eye's polygons was
  // most of the plots' time.  The names are ours; nothing reaches a shell.
  posix_spawn_file_actions_adddup2(&actions, pipe_ends[0], kScriptDescriptor);
  posix_spawn_file_actions_adddup2(&actions, process->output.fd(),
                                   kOutputDescriptor);
  char program[] = "gnuplot";
  char script[sizeof(kScriptPath)];
  std::memcpy(script, kScriptPath, sizeof(kScriptPath));
  // Set before the script, whose line numbers gnuplot's messages give;
  // `reset session` keeps it, so the documents follow each other.
  char output[] = "set output '/dev/fd/4'";
  static_assert(kOutputDescriptor == 4);
  char execute[] = "-e";
  char* argv[] = {program, execute, output, script, nullptr};
  const int spawned =
      posix_spawnp(&process->pid, program, &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  close(pipe_ends[0]);
  if (spawned != 0) {
    process->pid = 0;
    throw InputError(std::string("gnuplot failed: ") + std::strerror(spawned) +
                     " (is gnuplot-nox installed?)");
  }
  process_ = std::move(process);
}

SvgRendering::SvgRendering(const std::vector<SvgPlot>& plots) : SvgRendering() {
  Render(plots);
}

void SvgRendering::Render(const std::vector<SvgPlot>& plots) {
  CHECK(names_.empty()) << "SvgRendering::Render called twice";
  for (const SvgPlot& plot : plots) names_.push_back(plot.what);
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
         << plot.script << "\nreset session\n";
  }
  // A failed write means gnuplot has exited; Finish reports why.
  WriteToPipe(process_->script, full.str());
  process_->CloseScript();
}

SvgRendering::~SvgRendering() { Wait(); }

void SvgRendering::Wait() {
  if (!process_ || process_->pid == 0) return;
  process_->CloseScript();  // gnuplot ends at the script's end.
  while (waitpid(process_->pid, &process_->status, 0) < 0 && errno == EINTR) {
  }
  process_->pid = 0;
}

std::vector<std::string> SvgRendering::Finish() {
  if (names_.empty()) return {};
  Wait();
  const std::string text = process_->output.Read();
  std::vector<std::string> svgs;
  for (size_t begin = 0; svgs.size() < names_.size();) {
    const size_t end = text.find(kEndOfSvg, begin);
    if (end == std::string::npos) break;
    size_t next = end + std::strlen(kEndOfSvg);
    svgs.push_back(text.substr(begin, next - begin));
    // The blank line gnuplot ends a document's file with, mid-stream here.
    while (next < text.size() && text[next] == '\n') ++next;
    begin = next;
  }
  const size_t done = svgs.size();
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
