#include "pfdm/report/bullseye_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "pfdm/report/interval_text.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

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

bool UncertainSegment(const BullseyeMap& map, size_t r) {
  return r < map.half_widths.size() && Measured(map.half_widths[r]) &&
         map.half_widths[r] > map.uncertain_half_width;
}

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
        std::snprintf(value, sizeof(value), "%.1f%s", map.values[r],
                      UncertainSegment(map, r) ? "?" : "");
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

namespace {

// The maps' half-widths (peak Ecc's at its frame) and their rules.
void AddHalfWidths(const FitAnalysis& analysis, BullseyeMap* ecc,
                   BullseyeMap* radial, BullseyeMap* rotation) {
  const size_t es = analysis.ejection_fraction.es_frame;
  for (size_t r = 0; r < analysis.regions.size(); ++r) {
    ecc->half_widths.push_back(HalfWidth95(RegionSd(
        analysis, PeakEccFrame(analysis, r), r, &RegionMotion::ecc_percent)));
    radial->half_widths.push_back(HalfWidth95(
        RegionSd(analysis, es, r, &RegionMotion::radial_contraction_percent)));
    rotation->half_widths.push_back(
        HalfWidth95(RegionSd(analysis, es, r, &RegionMotion::rotation_deg)));
  }
  ecc->uncertain_half_width = kUncertainEccPercent;
  radial->uncertain_half_width = kUncertainContractionPercent;
  rotation->uncertain_half_width = kUncertainRotationDeg;
}

}  // namespace

std::vector<BullseyeMap> ClinicalBullseyeMaps(const FitAnalysis& analysis) {
  const int es = analysis.ejection_fraction.es_frame;
  BullseyeMap ecc{"peak Ecc, %", PeakRegionEcc(analysis.region_motion),
                  BullseyePalette::kShorteningRed};
  BullseyeMap ell{"peak Ell, %", PeakRegionEll(analysis.region_motion),
                  BullseyePalette::kShorteningRed};
  BullseyeMap radial{
      "radial contraction at ES, %", {}, BullseyePalette::kContractionRed};
  BullseyeMap thickening{
      "wall thickening at ES, %", {}, BullseyePalette::kContractionRed};
  BullseyeMap rotation{
      "rotation at ES, degrees", {}, BullseyePalette::kPurpleGreen};
  if (es < static_cast<int>(analysis.region_motion.size())) {
    for (const RegionMotion& m : analysis.region_motion[es]) {
      radial.values.push_back(m.radial_contraction_percent);
      thickening.values.push_back(m.thickening_percent);
      rotation.values.push_back(m.rotation_deg);
    }
  }
  if (analysis.sd.computed) AddHalfWidths(analysis, &ecc, &radial, &rotation);
  // At an ES without tracked points rotation is not measured: no map.  (The
  // apex cap alone may be n/a: no data near the apex.)
  bool measured = !rotation.values.empty();
  for (size_t r = 0; r < rotation.values.size(); ++r) {
    const bool cap =
        r < analysis.regions.size() && analysis.regions[r].level == kApex;
    if (!cap && !Measured(rotation.values[r])) measured = false;
  }
  std::vector<BullseyeMap> maps = {ecc, ell, radial};
  // A solid's walls have a thickness; one surface none.
  if (!analysis.models.empty() && analysis.models.front().config.Solid()) {
    maps.push_back(thickening);
  }
  if (measured) maps.push_back(rotation);
  return maps;
}

}  // namespace pfdm
