#include "pfdm/report/cycle_charts.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "pfdm/report/number_sd.h"
#include "pfdm/report/report_text.h"
#include "pfdm/report/segment_curves.h"
#include "pfdm/report/svg_chart.h"

namespace pfdm {
namespace {

struct Axis {
  std::vector<double> x;
  std::string label;
  bool timed = false;
  int ed = 0, es = 0;
};

Chart ChartOf(const Axis& axis, const std::string& title,
              const std::string& y_label, bool zero_line) {
  Chart chart;
  chart.title = title;
  chart.x_label = axis.label;
  chart.y_label = y_label;
  chart.x = axis.x;
  chart.ed = axis.ed;
  chart.es = axis.es;
  chart.zero_line = zero_line;
  return chart;
}

std::vector<double> Column(const std::vector<ClinicalSummary>& clinical,
                           double ClinicalSummary::*value) {
  std::vector<double> column;
  for (const ClinicalSummary& c : clinical) column.push_back(c.*value);
  return column;
}

// A clinical number per frame from `numbers` (the sds or the noise's
// biases), empty unless they were computed for every frame
// (--uncertainty off: never).
std::vector<double> ComputedColumn(const NumberSd& numbers,
                                   const FitAnalysis& analysis,
                                   double ClinicalSummary::*value) {
  if (!numbers.computed ||
      numbers.clinical.size() != analysis.clinical.size()) {
    return {};
  }
  return Column(numbers.clinical, value);
}

// GCS's or GLS's per frame from `numbers`, likewise.
std::vector<double> ComputedGlobalStrain(const NumberSd& numbers,
                                         const FitAnalysis& analysis,
                                         bool circumferential) {
  std::vector<double> column;
  if (!numbers.computed || numbers.strain.size() != analysis.strain.size()) {
    return column;
  }
  for (const GlobalStrain& g : numbers.strain) {
    column.push_back(circumferential ? g.gcs_percent : g.gls_percent);
  }
  return column;
}

std::vector<double> HalfWidths(std::vector<double> sds) {
  for (double& sd : sds) sd = HalfWidth95(sd);
  return sds;
}

// A clinical number's 95 % bars on `series`: half-widths, and centres the
// value minus its bias.
void SetBars(const FitAnalysis& analysis, double ClinicalSummary::*value,
             ChartSeries* series) {
  series->half_width = HalfWidths(ComputedColumn(analysis.sd, analysis, value));
  series->bias = ComputedColumn(analysis.noise_bias, analysis, value);
}

std::string VolumeCharts(const FitAnalysis& analysis, const Axis& axis) {
  const std::vector<double> volume =
      Column(analysis.clinical, &ClinicalSummary::volume_ml);
  std::vector<double> x_s = axis.x;
  if (axis.timed) {
    for (double& x : x_s) x /= 1000.0;
  }
  const std::vector<double> rate = VolumeRate(volume, x_s);
  const char* unit = axis.timed ? "ml/s" : "ml/frame";
  // Only the cavity's volumes give an ejection fraction.
  char title[96];
  if (analysis.volume_surface == "cavity") {
    std::snprintf(
        title, sizeof(title), "cavity volume, EF %s",
        WithUnit(100.0 * analysis.ejection_fraction.ratio, 1, " %").c_str());
  } else {
    std::snprintf(title, sizeof(title), "%s volume (not the cavity)",
                  analysis.volume_surface.c_str());
  }
  Chart v = ChartOf(axis, title, "ml", false);
  v.series.push_back({"volume (ml)", volume, "#1f3f8f", 2.0});
  SetBars(analysis, &ClinicalSummary::volume_ml, &v.series.back());
  Chart dv = ChartOf(axis, "dV/dt", unit, true);
  dv.series.push_back({std::string("dV/dt (") + unit + ")", rate, "#1f3f8f"});
  std::ostringstream h;
  h << ChartSvg(v) << ChartSvg(dv);
  if (axis.timed && !rate.empty()) {
    const VolumeRatePeaks peaks =
        PeakVolumeRates(rate, analysis.ejection_fraction.es_frame);
    char text[160];
    std::snprintf(text, sizeof(text),
                  "<p>Peak ejection rate <b>%.0f ml/s</b>, peak filling rate "
                  "<b>%.0f ml/s</b>.</p>",
                  peaks.ejection, peaks.filling);
    return h.str() + "</div>" + text + "<div class=\"charts\">";
  }
  return h.str();
}

std::string MotionCharts(const FitAnalysis& analysis, const Axis& axis) {
  const auto& c = analysis.clinical;
  std::ostringstream h;
  const std::vector<double> twist = Column(c, &ClinicalSummary::net_twist_deg);
  if (std::any_of(twist.begin(), twist.end(), Measured)) {
    Chart rotation =
        ChartOf(axis, "rotation about the LV axis", "degrees", true);
    rotation.series = {
        {"apex", Column(c, &ClinicalSummary::apex_rotation_deg), "#c0392b"},
        {"base", Column(c, &ClinicalSummary::base_rotation_deg), "#2471a3"},
        {"net twist", twist, "#222222", 2.0}};
    Chart torsion = ChartOf(axis, "torsion", "degrees/cm", true);
    torsion.series = {{"torsion",
                       Column(c, &ClinicalSummary::torsion_deg_per_cm),
                       "#6c3483", 2.0}};
    SetBars(analysis, &ClinicalSummary::net_twist_deg, &rotation.series[2]);
    SetBars(analysis, &ClinicalSummary::torsion_deg_per_cm, &torsion.series[0]);
    h << ChartSvg(rotation) << ChartSvg(torsion);
  }
  Chart contraction = ChartOf(axis, "contraction", "percent", true);
  contraction.series = {
      {"radial", Column(c, &ClinicalSummary::radial_contraction_percent),
       "#c0392b"},
      {"longitudinal",
       Column(c, &ClinicalSummary::longitudinal_shortening_percent),
       "#2471a3"}};
  SetBars(analysis, &ClinicalSummary::radial_contraction_percent,
          &contraction.series[0]);
  SetBars(analysis, &ClinicalSummary::longitudinal_shortening_percent,
          &contraction.series[1]);
  h << ChartSvg(contraction);
  return h.str();
}

std::string StrainCharts(const FitAnalysis& analysis, const Axis& axis) {
  std::ostringstream h;
  const char* const kLevels[] = {"basal", "mid", "apical"};
  const char* const kColors[] = {"#2471a3", "#27ae60", "#c0392b"};
  for (bool circumferential : {true, false}) {
    Chart chart = ChartOf(
        axis, circumferential ? "circumferential Ecc" : "longitudinal Ell",
        "percent", true);
    ChartSeries global{
        circumferential ? "GCS (global)" : "GLS (global)", {}, "#222222", 2.0};
    std::vector<ChartSeries> levels;
    for (int l = 0; l < 3; ++l) levels.push_back({kLevels[l], {}, kColors[l]});
    for (const GlobalStrain& g : analysis.strain) {
      global.y.push_back(circumferential ? g.gcs_percent : g.gls_percent);
      for (int l = 0; l < 3; ++l) {
        levels[l].y.push_back(circumferential ? g.level_ecc_percent[l]
                                              : g.level_ell_percent[l]);
      }
    }
    global.half_width = HalfWidths(
        ComputedGlobalStrain(analysis.sd, analysis, circumferential));
    global.bias =
        ComputedGlobalStrain(analysis.noise_bias, analysis, circumferential);
    chart.series = {global, levels[0], levels[1], levels[2]};
    h << ChartSvg(chart);
  }
  return h.str();
}

}  // namespace

std::vector<double> VolumeRate(const std::vector<double>& volume_ml,
                               const std::vector<double>& x) {
  const size_t n = std::min(volume_ml.size(), x.size());
  if (n < 2) return {};
  std::vector<double> rate;
  for (size_t t = 0; t < n; ++t) {
    const size_t a = t == 0 ? 0 : t - 1, b = t + 1 == n ? t : t + 1;
    rate.push_back((volume_ml[b] - volume_ml[a]) / (x[b] - x[a]));
  }
  return rate;
}

VolumeRatePeaks PeakVolumeRates(const std::vector<double>& rate, int es_frame) {
  VolumeRatePeaks peaks;
  for (size_t t = 0; t < rate.size(); ++t) {
    peaks.ejection = std::max(peaks.ejection, -rate[t]);
    if (static_cast<int>(t) >= es_frame) {
      peaks.filling = std::max(peaks.filling, rate[t]);
    }
  }
  return peaks;
}

std::string CycleChartsHtml(const FitAnalysis& analysis) {
  if (analysis.clinical.empty()) return "";
  Axis axis;
  axis.x = CycleX(analysis, &axis.timed);
  axis.label = axis.timed ? "time from the trigger (ms)" : "frame";
  axis.ed = analysis.ejection_fraction.ed_frame;
  axis.es = analysis.ejection_fraction.es_frame;
  std::ostringstream h;
  h << "<div class=\"charts\">" << VolumeCharts(analysis, axis)
    << MotionCharts(analysis, axis) << "</div>\n<div class=\"charts\">"
    << StrainCharts(analysis, axis) << "</div>\n";
  return h.str();
}

}  // namespace pfdm
