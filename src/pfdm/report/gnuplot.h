// Plots through gnuplot (Debian's gnuplot-nox), run as a child process.
#ifndef PFDM_REPORT_GNUPLOT_H_
#define PFDM_REPORT_GNUPLOT_H_

#include <memory>
#include <string>
#include <vector>

namespace pfdm {

// One named column block of data for a plot: rows of numbers.
struct PlotData {
  std::string name;  // Referred to in the script as $name.
  std::vector<std::vector<double>> rows;
};

// One plot: its data blocks, script and size; `what` names it in errors.
struct SvgPlot {
  std::string what;
  std::vector<PlotData> data;
  std::string script;
  int width = 900;
  int height = 600;
};

// Renders each plot as RenderSvgString would, all in one gnuplot process
// (`reset session` between them): starting gnuplot costs more than
// rendering one of the report's plots.  The SVGs in the plots' order;
// throws InputError naming the plot that failed.
std::vector<std::string> RenderSvgStrings(const std::vector<SvgPlot>& plots);

// RenderSvgStrings in three steps, so that gnuplot's start-up and its
// rendering overlap the caller's work: gnuplot starts at construction
// (throwing InputError if it cannot) and waits for its script on a pipe;
// Render hands it the plots (once); Finish waits for it and returns the
// SVGs or throws as RenderSvgStrings.  Destroyed unfinished, it ends
// gnuplot's script and waits for it, leaving no zombie behind.
class SvgRendering {
 public:
  SvgRendering();
  // SvgRendering() and Render(plots).
  explicit SvgRendering(const std::vector<SvgPlot>& plots);
  ~SvgRendering();
  SvgRendering(const SvgRendering&) = delete;
  SvgRendering& operator=(const SvgRendering&) = delete;

  void Render(const std::vector<SvgPlot>& plots);
  std::vector<std::string> Finish();

 private:
  struct Process;
  void Wait();

  std::vector<std::string> names_;
  std::unique_ptr<Process> process_;
};
std::string RenderSvgString(const SvgPlot& plot);

// Runs `script` with the data blocks defined first and the terminal set to
// SVG (width x height pixels), and returns the SVG.  gnuplot is started
// without a shell, the script on a pipe (/dev/fd/3) and the SVG on its
// standard output (an anonymous memory file), so no file name of the caller's
// ever reaches a shell or the script. Throws InputError(what + ": gnuplot
// failed: <gnuplot's error>") if gnuplot is missing or fails.
std::string RenderSvgString(const std::string& what,
                            const std::vector<PlotData>& data,
                            const std::string& script, int width = 900,
                            int height = 600);

// RenderSvgString written atomically to svg_path (named in errors).
void RenderSvg(const std::vector<PlotData>& data, const std::string& script,
               const std::string& svg_path, int width = 900, int height = 600);

}  // namespace pfdm

#endif  // PFDM_REPORT_GNUPLOT_H_
