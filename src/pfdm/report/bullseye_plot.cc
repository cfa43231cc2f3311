#include "pfdm/report/bullseye_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "pfdm/report/fit_plots.h"

namespace pfdm {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegreesPerRadian = 180.0 / kPi;
// Ring radii on the page: the apex cap inside 1, then one unit per level.
constexpr double kCapRadius = 1.0;
// Arc points every this many degrees.  On the outer ring (4 units, about
// 180 px) a chord then strays under a quarter pixel from its arc, r t^2 / 8.
constexpr double kArcStepDeg = 6.0;

double InnerRadius(RegionLevel level) {
  return level == kApex     ? 0.0
         : level == kApical ? kCapRadius
         : level == kMid    ? 2.0
                            : 3.0;
}

// A colour-scale half range holding every value, in round steps.
// A segment whose value the data cannot determine: unfilled, "n/a".
void NotMeasuredLabel(const WallRegion& region, double begin_deg,
                      double end_deg, std::ostringstream* script) {
  const double middle = (begin_deg + end_deg) / 2 / kDegreesPerRadian;
  const double radius = InnerRadius(region.level) + 0.5;
  *script << "set label 'n/a' at " << radius * std::cos(middle) << ','
          << radius * std::sin(middle)
          << " center front font 'sans,9' tc rgb '#777777'\n";
}

double ScaleOf(const std::vector<double>& values) {
  double largest = 0.0;
  for (double v : values) largest = std::max(largest, std::abs(v));
  const double step = largest > 20 ? 10.0 : largest > 4 ? 5.0 : 1.0;
  return std::max(step, step * std::ceil(largest / step));
}

// Light ends, so that the black labels stay legible on every segment.
const char* PaletteOf(BullseyePalette palette) {
  switch (palette) {
    case BullseyePalette::kShorteningRed:
      return "set palette defined (0 '#d6604d', 0.25 '#f4a582', 0.5 "
             "'#f7f7f7', 0.75 '#92c5de', 1 '#4393c3')\n";
    case BullseyePalette::kContractionRed:
      return "set palette defined (0 '#4393c3', 0.25 '#92c5de', 0.5 "
             "'#f7f7f7', 0.75 '#f4a582', 1 '#d6604d')\n";
    case BullseyePalette::kPurpleGreen:
      return "set palette defined (0 '#9970ab', 0.25 '#c2a5cf', 0.5 "
             "'#f7f7f7', 0.75 '#a6dba0', 1 '#5aae61')\n";
  }
  return "";
}

}  // namespace

std::pair<double, double> BullseyeSpanDeg(const WallRegion& region) {
  const double width = (region.v_end - region.v_begin) * kDegreesPerRadian;
  if (region.level == kApex) return {0.0, 360.0};
  const double begin = 90.0 - width / 2 + region.sector * width;
  return {begin, begin + width};
}

SvgPlot Bullseye(const std::vector<WallRegion>& regions,
                 const std::vector<BullseyeMap>& maps) {
  const int panels = static_cast<int>(maps.size());
  std::ostringstream script;
  script.precision(5);
  // The white dot at the centre makes gnuplot draw the colour box.
  std::vector<PlotData> data{{"centre", {{0.0, 0.0, 0.0}}}};
  script << "set multiplot layout 1," << panels
         << " margins 0.01,0.97,0.04,0.88 spacing 0.05,0\n"
         << "set size ratio -1\nunset border\nunset tics\nunset key\n"
         << "set xrange [-4.2:4.2]\nset yrange [-4.2:4.2]\n";
  for (int p = 0; p < panels; ++p) {
    const BullseyeMap& map = maps[p];
    const double scale = ScaleOf(map.values);
    script << "unset label\n"
           << PaletteOf(map.palette) << "set cbrange [" << -scale << ':'
           << scale << "]\n"
           << "set cbtics " << scale / 2 << " font 'sans,9'\n"
           << "set title '" << map.title << "' font 'sans,13'\n";
    // The segments as data, (x, y, value) around each outline, two blank
    // lines apart: a polygon object would have gnuplot parse each
    // coordinate as an expression, two sigaction(2) calls apiece.
    PlotData segments{"segments" + std::to_string(p), {}};
    for (size_t r = 0; r < regions.size() && r < map.values.size(); ++r) {
      const WallRegion& region = regions[r];
      const auto [begin, end] = BullseyeSpanDeg(region);
      if (!Measured(map.values[r])) {
        NotMeasuredLabel(region, begin, end, &script);
        continue;
      }
      const double inner = InnerRadius(region.level), outer = inner + 1.0;
      const int steps =
          std::max(2, static_cast<int>(std::ceil((end - begin) / kArcStepDeg)));
      // Not measured (the cap without data near the apex): white, "n/a".
      const double fill = std::isnan(map.values[r]) ? 0.0 : map.values[r];
      auto point = [&](double radius, double deg) {
        segments.rows.push_back({radius * std::cos(deg / kDegreesPerRadian),
                                 radius * std::sin(deg / kDegreesPerRadian),
                                 fill});
      };
      for (int i = 0; i <= steps; ++i) {
        point(outer, begin + (end - begin) * i / steps);
      }
      for (int i = steps; i >= 0; --i) {
        point(inner, begin + (end - begin) * i / steps);
      }
      point(outer, begin);  // Closes the border line.
      segments.rows.insert(segments.rows.end(), 2, std::vector<double>{});
      const double middle = (begin + end) / 2 / kDegreesPerRadian;
      const double radius = region.level == kApex ? 0.0 : inner + 0.5;
      char value[32];
      if (std::isnan(map.values[r])) {
        std::snprintf(value, sizeof(value), "n/a");
      } else {
        std::snprintf(value, sizeof(value), "%.1f", map.values[r]);
      }
      script << "set label '" << value << "' at " << radius * std::cos(middle)
             << ',' << radius * std::sin(middle)
             << " center front font 'sans,10' offset 0,-0.35\n"
             << "set label '" << region.segment << "' at "
             << radius * std::cos(middle) << ',' << radius * std::sin(middle)
             << " center front font 'sans,8' tc rgb '#333333' offset 0,0.55\n";
    }
    script << "set colorbox vertical user origin " << (p + 1.0) / panels - 0.035
           << ",0.18 size 0.012,0.6\n"
           << "plot ";
    if (!segments.rows.empty()) {
      // The border in a plot of its own: filledcurves draws it in the
      // fill's colour.
      script << '$' << segments.name
             << " using 1:2:3 with filledcurves closed fillcolor palette"
                " fs solid 1.0 noborder notitle, $"
             << segments.name
             << " using 1:2 with lines lc rgb '#404040' lw 1 notitle, ";
      data.push_back(std::move(segments));
    }
    script << "$centre using 1:2:3 with dots lc palette notitle\n";
  }
  script << "unset multiplot\n";
  return {"bullseye.svg", std::move(data), script.str(), 400 * panels, 430};
}

std::string BullseyeSvg(const std::vector<WallRegion>& regions,
                        const std::vector<BullseyeMap>& maps) {
  return RenderSvgString(Bullseye(regions, maps));
}

std::vector<BullseyeMap> ClinicalBullseyeMaps(const FitAnalysis& analysis) {
  const int es = analysis.ejection_fraction.es_frame;
  BullseyeMap ecc{"peak Ecc, %", PeakRegionEcc(analysis.region_motion),
                  BullseyePalette::kShorteningRed};
  BullseyeMap radial{
      "radial contraction at ES, %", {}, BullseyePalette::kContractionRed};
  BullseyeMap rotation{
      "rotation at ES, degrees", {}, BullseyePalette::kPurpleGreen};
  if (es < static_cast<int>(analysis.region_motion.size())) {
    for (const RegionMotion& m : analysis.region_motion[es]) {
      radial.values.push_back(m.radial_contraction_percent);
      rotation.values.push_back(m.rotation_deg);
    }
  }
  // At an ES without tracked points rotation is not measured: no map.  (The
  // apex cap alone may be n/a: no data near the apex.)
  bool measured = !rotation.values.empty();
  for (size_t r = 0; r < rotation.values.size(); ++r) {
    const bool cap =
        r < analysis.regions.size() && analysis.regions[r].level == kApex;
    if (!cap && !Measured(rotation.values[r])) measured = false;
  }
  if (!measured) return {ecc, radial};
  return {ecc, radial, rotation};
}

SvgPlot StrainCurves(const std::vector<GlobalStrain>& strain) {
  PlotData block{"strain", {}};
  for (size_t t = 0; t < strain.size(); ++t) {
    const GlobalStrain& g = strain[t];
    block.rows.push_back(
        {static_cast<double>(t), g.gcs_percent, g.level_ecc_percent[kBasal],
         g.level_ecc_percent[kMid], g.level_ecc_percent[kApical], g.gls_percent,
         g.level_ell_percent[kBasal], g.level_ell_percent[kMid],
         g.level_ell_percent[kApical]});
  }
  std::ostringstream script;
  script << "set multiplot layout 1,2 margins 0.06,0.98,0.14,0.82 "
            "spacing 0.08,0.1 title 'Lagrangian strain over the cycle "
            "(Green-Lagrange, against frame 0)' font 'sans,15'\n"
         << "set grid lc rgb '#dddddd'\nset xlabel 'frame'\n"
         << "set ylabel 'percent'\nset style data linespoints\n"
         << "set pointsize 0.6\n"
         << "set key bottom left opaque font 'sans,10' samplen 2\n";
  const char* panels[][2] = {{"circumferential Ecc", "GCS"},
                             {"longitudinal Ell", "GLS"}};
  for (int p = 0; p < 2; ++p) {
    const int first = 2 + 4 * p;
    script << "set title '" << panels[p][0] << "'\n"
           << "plot 0 notitle with lines dt 2 lc rgb '#888888', "
           << "$strain using 1:" << first << " lc rgb '#222222' pt 5 lw 2 "
           << "title '" << panels[p][1] << " (global)', "
           << "'' using 1:" << first + 1
           << " lc rgb '#2471a3' pt 7 title 'basal', "
           << "'' using 1:" << first + 2
           << " lc rgb '#27ae60' pt 7 title 'mid', "
           << "'' using 1:" << first + 3
           << " lc rgb '#c0392b' pt 7 title 'apical'\n";
  }
  script << "unset multiplot\n";
  return {"strain.svg", {block}, script.str(), 1200, 380};
}

std::string StrainCurvesSvg(const std::vector<GlobalStrain>& strain) {
  return RenderSvgString(StrainCurves(strain));
}

}  // namespace pfdm
