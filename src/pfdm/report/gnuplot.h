// Plots through gnuplot (Debian's gnuplot-nox), run as a child process.
#ifndef PFDM_REPORT_GNUPLOT_H_
#define PFDM_REPORT_GNUPLOT_H_

#include <string>
#include <vector>

namespace pfdm {

// One named column block of data for a plot: rows of numbers.
struct PlotData {
  std::string name;  // Referred to in the script as $name.
  std::vector<std::vector<double>> rows;
};

// Runs `script` with the data blocks defined first and the terminal set to
// SVG (width x height pixels), and returns the SVG.  gnuplot is started
// without a shell, the script on its standard input and the SVG on its
// standard output, so no file name ever reaches a shell or the script.
// Throws InputError(what + ": gnuplot failed: <gnuplot's error>") if gnuplot
// is missing or fails.
std::string RenderSvgString(const std::string& what,
                            const std::vector<PlotData>& data,
                            const std::string& script, int width = 900,
                            int height = 600);

// RenderSvgString written atomically to svg_path (named in errors).
void RenderSvg(const std::vector<PlotData>& data, const std::string& script,
               const std::string& svg_path, int width = 900, int height = 600);

}  // namespace pfdm

#endif  // PFDM_REPORT_GNUPLOT_H_
