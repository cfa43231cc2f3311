// Whether a frame's clinical numbers are ones a human heart can have, for
// data in millimetres: the analysis' part of each frame's verdict (the
// fit's own part: fit/stages/frame_verdict.h).  Each reason states its
// bounds (docs/verdict.md):
//   volume_range  the enclosed volume outside kMinVolumeMl..kMaxVolumeMl;
//   mass          LV mass negative or outside kMinMassG..kMaxMassG;
//   myocardium    the myocardium's volume changing from frame 0's by more
//                 than kMyocardiumWarn (failed beyond kMyocardiumFail, but
//                 a warning at most on a slab, below);
//   frame_motion  the volume changing between consecutive frames by more
//                 than kMaxFrameVolumeRatio either way;
//   ejection      an ejection fraction above kMaxEjectionFraction.
#ifndef PFDM_REPORT_PLAUSIBILITY_H_
#define PFDM_REPORT_PLAUSIBILITY_H_

#include <string>
#include <vector>

#include "pfdm/report/clinical_summary.h"
#include "pfdm/util/verdict.h"

namespace pfdm {

// Generous on purpose: they catch wrong units, wrong data and absurd fits,
// not disease.  A neonate's LV holds a few ml, a dilated adult's up to
// about 500 ml (mid-wall and epicardial volumes more), LV mass runs from
// about 10 g (neonate) to 500 g (severe hypertrophy).
constexpr double kMinVolumeMl = 2.0, kMaxVolumeMl = 1500.0;
constexpr double kMinMassG = 5.0, kMaxMassG = 1000.0;
// Myocardium is nearly incompressible: a few percent over the cycle.
constexpr double kMyocardiumWarn = 0.10, kMyocardiumFail = 0.25;
// A linear size changing by half (volume by 8) from one frame to the next.
constexpr double kMaxFrameVolumeRatio = 8.0;
constexpr double kMaxEjectionFraction = 0.9;

// The analysis' reasons for frame t.  volume_surface as
// FitAnalysis::volume_surface; the ejection fraction only when the cavity
// is measured.  `slab`: frame t's contours end at fixed image planes (no
// data near the apex, or the highest one short-axis slice), so its
// myocardium is the muscle between them, which it moves through: on the
// LV phantom's three mid-ventricular slices of both walls the truth's
// wall area in them grows by 22 % from ED to ES, and right fits read
// +17 to +36 %.
Verdict JudgeClinical(const std::vector<ClinicalSummary>& clinical,
                      const EjectionFraction& ejection,
                      const std::string& volume_surface, size_t t,
                      bool slab = false);

}  // namespace pfdm

#endif  // PFDM_REPORT_PLAUSIBILITY_H_
