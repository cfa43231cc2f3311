// One row per case of a cohort run: summary.csv.
#ifndef PFDM_BATCH_BATCH_SUMMARY_H_
#define PFDM_BATCH_BATCH_SUMMARY_H_

#include <string>
#include <vector>

namespace pfdm {

struct CaseSummary {
  std::string name;
  std::string status;  // "done", "failed" or "pending".
  // fit.json's quality.overall ("ok", "warning", "failed": implausible,
  // util/verdict.h), "" for a fit.json from before verdicts; and the
  // distinct reason codes of its frames, in order of first appearance.
  std::string quality;
  std::vector<std::string> quality_reasons;
  int frames = 0;
  double max_rms_mm = 0.0;
  // What the volumes enclose (fit.json model.volume_surface): "cavity",
  // "midwall" or "epicardial".  The ejection fraction is only the cavity's:
  // the summary leaves it empty for the others.
  std::string volume_surface = "cavity";
  double edv_ml = 0.0;  // ED and ES volumes of that surface.
  double esv_ml = 0.0;
  int es_frame = 0;
  double ejection_fraction = 0.0;  // Ratio, (EDV - ESV) / EDV.
  // A solid's LV mass at ED (g) and wall thickening at ES (percent).
  bool solid = false;
  double lv_mass_g = 0.0;
  double wall_thickening_percent = 0.0;
  // At ES, the frame of least volume.  twist_measured is false where
  // fit.json's net twist is null (an ES without tracked points: contours):
  // an empty column, as the CSV leaves every number that does not apply.
  bool twist_measured = true;
  double net_twist_deg = 0.0;
  double longitudinal_shortening_percent = 0.0;
  double radial_contraction_percent = 0.0;  // Mean of x and y.
  // Peak (most negative over the frames) global circumferential and
  // longitudinal Green-Lagrange strain, percent; has_strain is false for a
  // fit.json written before strain was reported (empty columns).
  bool has_strain = false;
  double peak_gcs_percent = 0.0;
  double peak_gls_percent = 0.0;
  std::string error;  // For a failed case.
  // The half-widths of the 95 % intervals of the numbers above (fit.json's
  // "<key>_ci95", --uncertainty on), in kHalfWidthColumns' order; NaN where
  // fit.json has none.  has_intervals: fit.json has any.
  bool has_intervals = false;
  std::vector<double> half_widths;
};

// summary.csv's half-width columns, written after the others when some
// case has intervals: "<column>_hw95", the half-width of its 95 % interval.
extern const char* const kHalfWidthColumns[10];

// The numbers of a finished case, read back from its fit.json text, so a
// resumed run summarizes cases it skipped exactly like ones it fitted.
// Throws InputError naming `where` when the text is not a pfdm fit.json.
CaseSummary SummaryFromFitJson(const std::string& name,
                               const std::string& json_text,
                               const std::string& where);

// Header and one row per case; text fields quoted where they need it.
std::string SummaryCsv(const std::vector<CaseSummary>& cases);

}  // namespace pfdm

#endif  // PFDM_BATCH_BATCH_SUMMARY_H_
