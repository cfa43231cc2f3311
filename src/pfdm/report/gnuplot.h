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
// SVG (width x height pixels) writing to a temporary file that is renamed
// to svg_path when gnuplot succeeds.  Throws InputError naming svg_path if
// gnuplot is missing or fails.
void RenderSvg(const std::vector<PlotData>& data, const std::string& script,
               const std::string& svg_path, int width = 900, int height = 600);

}  // namespace pfdm

#endif  // PFDM_REPORT_GNUPLOT_H_
