#include "pfdm/report/gnuplot.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "pfdm/util/atomic_file.h"
#include "pfdm/util/error.h"

namespace pfdm {

void RenderSvg(const std::vector<PlotData>& data, const std::string& script,
               const std::string& svg_path, int width, int height) {
  const std::string temporary = svg_path + ".tmp." + std::to_string(getpid());
  const std::string script_path = temporary + ".gp";
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
       << "set output '" << temporary << "'\n"
       << script << "\nunset output\n";
  WriteFileAtomically(script_path, full.str());
  const std::string command =
      "gnuplot '" + script_path + "' 2>'" + script_path + ".log'";
  const int status = std::system(command.c_str());
  std::string log;
  {
    std::ifstream in(script_path + ".log");
    std::getline(in, log);
  }
  std::filesystem::remove(script_path);
  std::filesystem::remove(script_path + ".log");
  if (status != 0 || !std::filesystem::exists(temporary)) {
    std::filesystem::remove(temporary);
    throw InputError(
        svg_path + ": gnuplot failed" +
        (log.empty() ? " (is gnuplot-nox installed?)" : ": " + log));
  }
  std::filesystem::rename(temporary, svg_path);
}

}  // namespace pfdm
