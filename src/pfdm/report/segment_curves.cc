#include "pfdm/report/segment_curves.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "pfdm/report/report_text.h"
#include "pfdm/report/svg_chart.h"
#include "pfdm/util/markup_escape.h"

namespace pfdm {
namespace {

const char* const kSectorColors[] = {"#1f77b4", "#d62728", "#2ca02c",
                                     "#9467bd", "#ff7f0e", "#17becf"};

Chart LevelChart(const FitAnalysis& analysis, RegionLevel level,
                 const std::vector<double>& x, bool timed) {
  static const char* const kTitles[] = {"basal Ecc", "mid Ecc", "apical Ecc"};
  Chart chart;
  chart.title = kTitles[level];
  chart.x_label = timed ? "time from the trigger (ms)" : "frame";
  chart.y_label = "percent";
  chart.x = x;
  chart.ed = analysis.ejection_fraction.ed_frame;
  chart.es = analysis.ejection_fraction.es_frame;
  chart.zero_line = true;
  chart.width = 360;
  for (size_t r = 0; r < analysis.regions.size(); ++r) {
    const WallRegion& region = analysis.regions[r];
    if (region.level != level) continue;
    ChartSeries series{std::to_string(region.segment) + " " + region.Name(),
                       {},
                       kSectorColors[region.sector % 6]};
    for (const auto& motion : analysis.region_motion) {
      series.y.push_back(motion[r].ecc_percent);
    }
    chart.series.push_back(series);
  }
  return chart;
}

std::string TimingTable(const FitAnalysis& analysis,
                        const std::vector<double>& x, bool timed) {
  const Dyssynchrony& d = analysis.dyssynchrony;
  const char* unit = d.in_ms ? "ms" : "frames";
  std::ostringstream h;
  h << "<table><tr><th>segment</th><th>peak Ecc (%)</th><th>at "
    << (timed ? "(ms)" : "frame") << "</th><th>time to peak (" << unit
    << ")</th></tr>";
  for (size_t r = 0; r < analysis.regions.size() && r < d.peaks.size(); ++r) {
    const SegmentPeak& peak = d.peaks[r];
    const bool measured = peak.frame >= 0;
    h << "<tr><td>" << analysis.regions[r].segment << ' '
      << EscapeMarkup(analysis.regions[r].Name()) << "</td><td>"
      << Fixed(peak.percent, 1) << "</td><td>"
      << (measured ? Fixed(x[peak.frame], 0) : "n/a") << "</td><td>"
      << Fixed(peak.time_to_peak, d.in_ms ? 0 : 1) << "</td></tr>";
  }
  h << "</table>\n";
  return h.str();
}

}  // namespace

std::vector<double> CycleX(const FitAnalysis& analysis, bool* timed) {
  *timed =
      !analysis.clinical.empty() &&
      std::all_of(analysis.clinical.begin(), analysis.clinical.end(),
                  [](const ClinicalSummary& s) { return Measured(s.time_ms); });
  std::vector<double> x;
  for (size_t t = 0; t < analysis.clinical.size(); ++t) {
    x.push_back(*timed ? analysis.clinical[t].time_ms : static_cast<double>(t));
  }
  return x;
}

std::string SegmentCurvesHtml(const FitAnalysis& analysis) {
  if (analysis.region_motion.empty()) return "";
  bool timed = false;
  const std::vector<double> x = CycleX(analysis, &timed);
  const Dyssynchrony& d = analysis.dyssynchrony;
  std::ostringstream h;
  h << "<h2>Segments over the cycle</h2>\n<div class=\"charts\">";
  for (RegionLevel level : {kBasal, kMid, kApical}) {
    h << ChartSvg(LevelChart(analysis, level, x, timed));
  }
  h << "</div>\n<p><b>Dyssynchrony index</b> (the standard deviation of the "
       "time from ED to peak Ecc over "
    << d.segments << " segments): <b>"
    << (Measured(d.index)
            ? Fixed(d.index, d.in_ms ? 0 : 2) + (d.in_ms ? " ms" : " frames")
            : std::string("n/a (fewer than 2 segments measured)"))
    << "</b>.</p>\n"
    << TimingTable(analysis, x, timed)
    << "<p class=\"note\">Each segment's Lagrangian Ecc against ED, its "
       "peak the most negative value over the frames; hover over a curve "
       "for its values. Segments not measured in some frame are left out of "
       "the index, and so is the apex cap (17), whose circumferential "
       "direction "
       "turns about its pole. "
    << (d.in_ms ? "" : "The frames' times are not known: times in frames. ")
    << "</p>\n";
  return h.str();
}

}  // namespace pfdm
