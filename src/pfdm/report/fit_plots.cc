#include "pfdm/report/fit_plots.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "pfdm/report/gnuplot.h"
#include "pfdm/report/number_sd.h"
#include "pfdm/util/angles.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

// Frame t of n on a dark-blue to orange ramp, so systole reads as a
// progression without a legend lookup; "#rrggbb".
std::string FrameColor(int t, int n) {
  static const double kStops[][3] = {{0.12, 0.16, 0.45},
                                     {0.15, 0.55, 0.62},
                                     {0.55, 0.75, 0.30},
                                     {0.95, 0.55, 0.10}};
  const double x = n > 1 ? 3.0 * t / (n - 1) : 0.0;
  const int i = std::min(2, static_cast<int>(x));
  const double w = x - i;
  char color[8];
  int rgb[3];
  for (int c = 0; c < 3; ++c) {
    rgb[c] = static_cast<int>(
        std::lround(255.0 * ((1 - w) * kStops[i][c] + w * kStops[i + 1][c])));
  }
  std::snprintf(color, sizeof(color), "#%02x%02x%02x", rgb[0], rgb[1], rgb[2]);
  return color;
}

// The 95 % half-widths of frame `model`'s plotted values at knot k (the
// columns of ParameterPlots after the knot), 0 without a covariance.
std::vector<double> KnotHalfWidths(const Model& model, const Model& ed,
                                   const FrameCovariance* covariance, int k,
                                   double degrees, bool reference) {
  static const int kColumns[] = {kA1, kA2, kA3, kTau, kB0, kB2, kH, kDtau};
  std::vector<double> widths;
  const double u = model.config.Grid().KnotU(k);
  for (int f : kColumns) {
    double sd = covariance != nullptr && covariance->computed
                    ? covariance->KnotSd(model.config, f, k)
                    : 0.0;
    // Frame 0's ratios are 1 by definition.
    if (f == kA1 || f == kA2 || f == kA3)
      sd *= reference ? 0.0 : 1.0 / ed.FunctionAt(f, u);
    if (f == kTau || f == kDtau) sd *= degrees;
    widths.push_back(HalfWidth95(sd));
  }
  return widths;
}

}  // namespace

SvgPlot ParameterPlots(const std::vector<Model>& frames,
                       const std::vector<bool>& rotation_measured,
                       const std::vector<FrameCovariance>& covariances,
                       int es_frame) {
  const int n = static_cast<int>(frames.size());
  const int knots = frames.front().config.num_knots;
  const KnotGrid grid = frames.front().config.Grid();
  const Model& ed = frames.front();
  // One block per frame, separated by two blank lines (gnuplot's "index").
  PlotData block{"knots", {}};
  bool any_twist = false;
  for (int t = 0; t < n; ++t) {
    if (t > 0) block.rows.insert(block.rows.end(), 2, {});
    // gnuplot skips the NaN of a held twist.
    const bool twist =
        t >= static_cast<int>(rotation_measured.size()) || rotation_measured[t];
    any_twist = any_twist || twist;
    const double degrees = twist ? kDegreesPerRadian : kNotMeasured;
    for (int k = 0; k < knots; ++k) {
      const double u = grid.KnotU(k);
      const Model& m = frames[t];
      block.rows.push_back(
          {static_cast<double>(k), m.FunctionAt(kA1, u) / ed.FunctionAt(kA1, u),
           m.FunctionAt(kA2, u) / ed.FunctionAt(kA2, u),
           m.FunctionAt(kA3, u) / ed.FunctionAt(kA3, u),
           m.FunctionAt(kTau, u) * degrees, m.FunctionAt(kB0, u),
           m.FunctionAt(kB2, u), m.FunctionAt(kH, u),
           m.FunctionAt(kDtau, u) * degrees});
      const bool has = t < static_cast<int>(covariances.size());
      const std::vector<double> widths = KnotHalfWidths(
          m, ed, has ? &covariances[t] : nullptr, k, degrees, t == 0);
      block.rows.back().insert(block.rows.back().end(), widths.begin(),
                               widths.end());
    }
  }
  std::ostringstream colors;
  for (int t = 0; t < n; ++t) colors << (t ? " " : "") << FrameColor(t, n);
  const bool solid = ed.config.Solid();
  std::ostringstream script;
  // The lines coloured by frame on a colour bar, not a legend line each;
  // ED (frame 0) and ES drawn thicker; each line's title, shown on hover.
  script << "colors = '" << colors.str() << "'\nset palette defined (";
  for (int i = 0; i < 4; ++i) {
    script << (i ? ", " : "") << i * std::max(1, n - 1) / 3.0 << " '"
           << FrameColor(i, 4) << "'";
  }
  script << ")\nset cbrange [0:" << std::max(1, n - 1) << "]\n"
         << "set cblabel 'frame'\nunset key\n"
         << "set colorbox user origin screen 0.925,0.35 size screen 0.012,0.5\n"
         << "es = " << es_frame << "\n"
         << "set multiplot layout " << (solid ? 3 : 2)
         << ",3 margins 0.05,0.9,0.09,0.92 "
            "spacing 0.06,0.13 title 'Parameter functions, apex to base, "
            "coloured by frame' font 'sans,15'\n"
         << "set grid lc rgb '#dddddd'\n"
         << "set xrange [0:" << knots - 1 << "]\n"
         << "set xtics 0," << std::max(1, (knots - 1) / 4) << "\n"
         << "set xlabel 'knot (0 = apex, " << knots - 1 << " = base)'\n"
         << "set style data linespoints\n"
         << "set pointsize 0.5\n";
  struct Panel {
    int column;
    const char* title;
    const char* reference;  // A dashed line where no motion would be.
  };
  const Panel panels[] = {
      {2, "radial: a1 / a1 at frame 0", "1"},
      {3, "radial: a2 / a2 at frame 0", "1"},
      {4, "longitudinal: a3 / a3 at frame 0", "1"},
      {5, "twist tau (degrees)", "0"},
      {6, "bending b0 (mm)", "0"},
      {7, "bending b2 (mm)", "0"},
      {8, "wall thickness h (mm)", "0"},
      {9, "epi minus endo twist dtau (degrees)", "0"},
  };
  const bool bands =
      std::any_of(covariances.begin(), covariances.end(),
                  [](const FrameCovariance& c) { return c.computed; });
  bool first = true;
  for (const Panel& p : panels) {
    if (!solid && p.column > 7) break;
    script << "set title '" << p.title << "'\n";
    const bool twist_panel = p.column == 5 || p.column == 9;
    if (twist_panel && !any_twist) {
      script << "set label 1 'n/a: no tracked points' at graph 0.5,0.5 "
                "center\n";
    }
    if (!first) script << "unset colorbox\n";
    script << "plot " << p.reference
           << " title 'no change' with lines dt 2 lc rgb '#888888', ";
    if (bands) {  // The 95 % bands under the lines.
      const int c = p.column, w = p.column + 8;
      script << "for [t=0:" << n - 1 << "] $knots index t using 1:($" << c
             << "-$" << w << "):($" << c << "+$" << w
             << ") with filledcurves lc rgb word(colors, t + 1) "
                "fs transparent solid 0.18 noborder notitle, ";
    }
    script << "for [t=0:" << n - 1 << "] $knots index t using 1:" << p.column
           << " lc palette cb t lw (t == 0 || t == es ? 2.5 : 1) pt 7 "
              "title sprintf('frame %d%s', t, t == 0 ? ' (ED)' : t == es ? "
              "' (ES)' : '')\n";
    if (twist_panel && !any_twist) script << "unset label 1\n";
    first = false;
  }
  script << "unset multiplot\n";
  return {"parameters.svg", {block}, script.str(), 1200, solid ? 1100 : 760};
}

std::string ParameterPlotsSvg(const std::vector<Model>& frames,
                              const std::vector<bool>& rotation_measured,
                              const std::vector<FrameCovariance>& covariances,
                              int es_frame) {
  return RenderSvgString(
      ParameterPlots(frames, rotation_measured, covariances, es_frame));
}

}  // namespace pfdm
