#include "pfdm/report/fit_plots.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "pfdm/report/gnuplot.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;

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

}  // namespace

SvgPlot ParameterPlots(const std::vector<Model>& frames,
                       const std::vector<bool>& rotation_measured) {
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
    }
  }
  std::ostringstream colors;
  for (int t = 0; t < n; ++t) colors << (t ? " " : "") << FrameColor(t, n);
  const bool solid = ed.config.Solid();
  std::ostringstream script;
  script << "colors = '" << colors.str() << "'\n"
         << "set multiplot layout " << (solid ? 3 : 2)
         << ",3 margins 0.05,0.9,0.09,0.92 "
            "spacing 0.06,0.13 title 'Parameter functions, apex to base, "
            "one line per frame' font 'sans,15'\n"
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
  bool first = true;
  for (const Panel& p : panels) {
    if (!solid && p.column > 7) break;
    script << "set title '" << p.title << "'\n";
    const bool twist_panel = p.column == 5 || p.column == 9;
    if (twist_panel && !any_twist) {
      script << "set label 1 'n/a: no tracked points' at graph 0.5,0.5 "
                "center\n";
    }
    if (first) {
      script << "set key at screen 0.995,0.92 top right Left reverse "
                "samplen 2 spacing 0.9 font 'sans,10' title 'frame'\n";
    } else {
      script << "unset key\n";
    }
    script << "plot " << p.reference
           << " notitle with lines dt 2 lc rgb '#888888', "
           << "for [t=0:" << n - 1 << "] $knots index t using 1:" << p.column
           << " lc rgb word(colors, t + 1) pt 7 title sprintf('%d', t)\n";
    if (twist_panel && !any_twist) script << "unset label 1\n";
    first = false;
  }
  script << "unset multiplot\n";
  return {"parameters.svg", {block}, script.str(), 1200, solid ? 1100 : 760};
}

std::string ParameterPlotsSvg(const std::vector<Model>& frames,
                              const std::vector<bool>& rotation_measured) {
  return RenderSvgString(ParameterPlots(frames, rotation_measured));
}

SvgPlot CycleCurves(const std::vector<ClinicalSummary>& summaries,
                    const std::string& volume_surface, int ed_frame) {
  // Against the time from the trigger where every frame has one, else the
  // frame number.
  const bool timed =
      !summaries.empty() &&
      std::all_of(summaries.begin(), summaries.end(),
                  [](const ClinicalSummary& s) { return Measured(s.time_ms); });
  auto x_of = [&](const ClinicalSummary& s) {
    return timed ? s.time_ms : static_cast<double>(s.frame);
  };
  PlotData block{"cycle", {}};
  for (const ClinicalSummary& s : summaries) {
    block.rows.push_back({x_of(s), s.volume_ml, s.apex_rotation_deg,
                          s.base_rotation_deg, s.net_twist_deg,
                          s.radial_contraction_percent,
                          s.longitudinal_shortening_percent});
  }
  const EjectionFraction ef = EjectionFractionOf(summaries, ed_frame);
  const double ed_x = summaries.empty() ? 0.0 : x_of(summaries[ef.ed_frame]);
  const double es_x = summaries.empty() ? 0.0 : x_of(summaries[ef.es_frame]);
  // Rows of unmeasured rotations hold NaN, which gnuplot skips; with none
  // measured (contours) the panel would show nothing, and goes.
  const bool any_rotation = std::any_of(
      summaries.begin(), summaries.end(),
      [](const ClinicalSummary& s) { return Measured(s.net_twist_deg); });
  std::ostringstream script;
  script.precision(4);
  script << "set multiplot layout 1," << (any_rotation ? 3 : 2)
         << " margins 0.06,0.98,0.14,0.8 "
            "spacing 0.07,0.1 title 'Over the cycle' font 'sans,15'\n"
         << "set grid lc rgb '#dddddd'\nset xlabel '"
         << (timed ? "time from the trigger (ms)" : "frame") << "'\n"
         << "set style data linespoints\nset pointsize 0.6\n"
         << "unset key\n"
         << (volume_surface == "cavity"
                 ? "set title sprintf('cavity volume, EF %.1f %%', " +
                       std::to_string(100.0 * ef.ratio) + ")"
                 : "set title '" + volume_surface + " volume (not the cavity)'")
         << "\nset ylabel 'ml'\n"
         << "set label 1 'ED' at " << ed_x << ',' << ef.edv_ml
         << " offset 0.5,0.8\n"
         << "set label 2 'ES' at " << es_x << ',' << ef.esv_ml
         << " offset 0,-1\n"
         << "plot $cycle using 1:2 lc rgb '#1f3f8f' pt 7 title 'volume'\n"
         << "unset label 1\nunset label 2\n"
         << "set key top right opaque font 'sans,10' samplen 2\n";
  if (any_rotation) {
    script << "set title 'rotation about the LV axis'\nset ylabel 'degrees'\n"
           << "plot 0 notitle with lines dt 2 lc rgb '#888888', "
              "$cycle using 1:3 lc rgb '#c0392b' pt 7 title 'apex', "
              "'' using 1:4 lc rgb '#2471a3' pt 7 title 'base', "
              "'' using 1:5 lc rgb '#222222' pt 5 lw 2 title 'net twist'\n";
  }
  script << "set title 'contraction'\nset ylabel 'percent'\n"
         << "plot 0 notitle with lines dt 2 lc rgb '#888888', "
            "$cycle using 1:6 lc rgb '#c0392b' pt 7 title 'radial', "
            "'' using 1:7 lc rgb '#2471a3' pt 5 title 'longitudinal'\n"
         << "unset multiplot\n";
  return {"cycle.svg", {block}, script.str(), 1200, 380};
}

std::string CycleCurvesSvg(const std::vector<ClinicalSummary>& summaries,
                           const std::string& volume_surface, int ed_frame) {
  return RenderSvgString(CycleCurves(summaries, volume_surface, ed_frame));
}

}  // namespace pfdm
