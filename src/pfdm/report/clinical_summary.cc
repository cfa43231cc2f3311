#include "pfdm/report/clinical_summary.h"

#include <cmath>

#include "pfdm/model/model_surface.h"

namespace pfdm {
namespace {

constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;

double AxialLength(const Model& model) {
  const double a0 = model.state.globals[kA0];
  const double u_min = model.config.u_min, u_max = model.config.u_max;
  return a0 * (model.FunctionAt(kA3, u_max) * std::sin(u_max) -
               model.FunctionAt(kA3, u_min) * std::sin(u_min)) +
         model.FunctionAt(kE3o, u_max) - model.FunctionAt(kE3o, u_min);
}

}  // namespace

int ApicalKnot(const ModelConfig& config) {
  const KnotGrid grid = config.Grid();
  for (int k = 0; k < grid.num_knots(); ++k) {
    if (std::cos(grid.KnotU(k)) > 1e-6) return k;
  }
  return 0;
}

ClinicalSummary SummarizeFrame(int frame, const Model& reference,
                               const Model& current) {
  const KnotGrid grid = current.config.Grid();
  const int apical = ApicalKnot(current.config);
  ClinicalSummary summary;
  summary.frame = frame;
  summary.apex_rotation_deg =
      current.FunctionAt(kTau, grid.KnotU(apical)) * kDegreesPerRadian;
  summary.base_rotation_deg =
      current.FunctionAt(kTau, grid.u_max()) * kDegreesPerRadian;
  summary.net_twist_deg = summary.base_rotation_deg - summary.apex_rotation_deg;
  int counted = 0;
  for (int k = 0; k < grid.num_knots(); ++k) {
    const double u = grid.KnotU(k);
    auto ratio = [&](int f) {
      return current.FunctionAt(f, u) / reference.FunctionAt(f, u);
    };
    summary.radial_ratio_x.push_back(ratio(kA1));
    summary.radial_ratio_y.push_back(ratio(kA2));
    summary.longitudinal_ratio.push_back(ratio(kA3));
    if (k < apical) continue;
    summary.radial_contraction_x_percent += 100.0 * (1.0 - ratio(kA1));
    summary.radial_contraction_y_percent += 100.0 * (1.0 - ratio(kA2));
    ++counted;
  }
  summary.radial_contraction_x_percent /= counted;
  summary.radial_contraction_y_percent /= counted;
  summary.longitudinal_shortening_percent =
      100.0 * (1.0 - AxialLength(current) / AxialLength(reference));
  summary.volume_ml = CavityVolumeMl(current);
  return summary;
}

std::vector<ClinicalSummary> SummarizeSequence(
    const std::vector<Model>& frames) {
  std::vector<ClinicalSummary> summaries;
  for (size_t t = 0; t < frames.size(); ++t) {
    summaries.push_back(
        SummarizeFrame(static_cast<int>(t), frames.front(), frames[t]));
  }
  return summaries;
}

EjectionFraction EjectionFractionOf(
    const std::vector<ClinicalSummary>& summaries) {
  EjectionFraction ef;
  if (summaries.empty()) return ef;
  ef.ed_frame = summaries.front().frame;
  ef.edv_ml = summaries.front().volume_ml;
  ef.es_frame = ef.ed_frame;
  ef.esv_ml = ef.edv_ml;
  for (const ClinicalSummary& s : summaries) {
    if (s.volume_ml < ef.esv_ml) {
      ef.es_frame = s.frame;
      ef.esv_ml = s.volume_ml;
    }
  }
  if (ef.edv_ml > 0.0) ef.ratio = (ef.edv_ml - ef.esv_ml) / ef.edv_ml;
  return ef;
}

}  // namespace pfdm
