#include "pfdm/report/plausibility.h"

#include <cmath>
#include <cstdio>

namespace pfdm {
namespace {

std::string Format(const char* format, double a, double b = 0.0, double c = 0.0,
                   double d = 0.0) {
  char text[256];
  std::snprintf(text, sizeof(text), format, a, b, c, d);
  return text;
}

void JudgeVolume(const ClinicalSummary& c, const std::string& surface,
                 Verdict* verdict) {
  if (!Measured(c.volume_ml)) return;
  if (c.volume_ml >= kMinVolumeMl && c.volume_ml <= kMaxVolumeMl) return;
  verdict->Fail("volume_range",
                surface + Format(" volume %.3g ml is outside %g-%g ml (are the "
                                 "data in mm?)",
                                 c.volume_ml, kMinVolumeMl, kMaxVolumeMl));
}

void JudgeMass(const ClinicalSummary& c, Verdict* verdict) {
  if (!c.solid) return;
  if (c.lv_mass_g < 0.0) {
    verdict->Fail("mass", Format("LV mass %.3g g is negative: the walls cross",
                                 c.lv_mass_g));
  } else if (c.lv_mass_g < kMinMassG || c.lv_mass_g > kMaxMassG) {
    verdict->Fail("mass", Format("LV mass %.3g g is outside %g-%g g",
                                 c.lv_mass_g, kMinMassG, kMaxMassG));
  }
}

void JudgeMyocardium(const ClinicalSummary& first, const ClinicalSummary& c,
                     bool slab, Verdict* verdict) {
  if (!c.solid || !(first.myocardial_volume_ml > 0.0) ||
      !Measured(c.myocardial_volume_ml)) {
    return;
  }
  const double change = c.myocardial_volume_ml / first.myocardial_volume_ml - 1;
  if (std::abs(change) <= kMyocardiumWarn) return;
  std::string text = Format(
      "the myocardium's volume changes %+.0f %% from frame 0's "
      "(%.1f to %.1f ml; muscle keeps its volume within a few %%)",
      100.0 * change, first.myocardial_volume_ml, c.myocardial_volume_ml);
  if (slab) {
    text +=
        ", but these contours end at image planes that muscle moves "
        "through, where it need not";
  }
  if (std::abs(change) > kMyocardiumFail && !slab) {
    verdict->Fail("myocardium", text);
  } else {
    verdict->Warn("myocardium", text);
  }
}

void JudgeFrameMotion(const ClinicalSummary& before, const ClinicalSummary& c,
                      const std::string& surface, Verdict* verdict) {
  if (!(before.volume_ml > 0.0) || !(c.volume_ml > 0.0)) return;
  const double ratio = c.volume_ml / before.volume_ml;
  if (ratio <= kMaxFrameVolumeRatio && ratio >= 1.0 / kMaxFrameVolumeRatio) {
    return;
  }
  verdict->Fail(
      "frame_motion",
      surface + Format(" volume goes from %.3g to %.3g ml between "
                       "frames %.0f and %.0f: no heart moves so",
                       before.volume_ml, c.volume_ml, before.frame, c.frame));
}

}  // namespace

Verdict JudgeClinical(const std::vector<ClinicalSummary>& clinical,
                      const EjectionFraction& ejection,
                      const std::string& volume_surface, size_t t, bool slab) {
  Verdict verdict;
  const ClinicalSummary& c = clinical[t];
  JudgeVolume(c, volume_surface, &verdict);
  JudgeMass(c, &verdict);
  JudgeMyocardium(clinical.front(), c, slab, &verdict);
  if (t > 0) JudgeFrameMotion(clinical[t - 1], c, volume_surface, &verdict);
  if (volume_surface == "cavity" && static_cast<int>(t) == ejection.es_frame &&
      ejection.ratio > kMaxEjectionFraction) {
    verdict.Fail("ejection",
                 Format("ejection fraction %.2f is above any heart's (%.2f)",
                        ejection.ratio, kMaxEjectionFraction));
  }
  return verdict;
}

}  // namespace pfdm
