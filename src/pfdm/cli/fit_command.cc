// pfdm fit: fits every frame and writes fit.json, plots, report and meshes.
#include <cstdio>

#include "pfdm/cli/commands.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/io/fit_output.h"
#include "pfdm/io/landmark_axis.h"
#include "pfdm/io/mitral_valve_planes.h"
#include "pfdm/io/rv_insertion_source.h"
#include "pfdm/report/fit_analysis.h"
#include "pfdm/report/gnuplot.h"
#include "pfdm/util/error.h"
#include "pfdm/util/verdict.h"

namespace pfdm {

namespace {

// One stdout line per frame with its quality; the reasons of every frame
// that is not ok on stderr, and what the whole fit amounts to.  Returns
// the exit code: kExitImplausible when a frame failed.
int ReportQuality(const SequenceFit& fit, const FitAnalysis& analysis) {
  int warnings = 0, failures = 0;
  for (size_t t = 0; t < fit.frames.size(); ++t) {
    const FrameFit& frame = fit.frames[t];
    const Verdict& verdict = analysis.verdicts[t];
    std::printf("frame %3d  points %5zu  rms %.3f mm  max %.3f mm  %s%s  %s\n",
                frame.frame, frame.residuals.size(), frame.rms_mm,
                frame.max_distance_mm, frame.termination.c_str(),
                UnsettledNote(frame).c_str(), QualityName(verdict.quality()));
    if (verdict.quality() == Quality::kOk) continue;
    std::fprintf(stderr, "pfdm: frame %d: %s\n", frame.frame,
                 verdict.Summary().c_str());
    warnings += verdict.quality() == Quality::kWarning;
    failures += verdict.quality() == Quality::kFailed;
  }
  if (failures > 0) {
    std::fprintf(stderr,
                 "pfdm: the fit is implausible: %d of %zu frames failed (exit "
                 "%d; outputs written, fit.json says why)\n",
                 failures, fit.frames.size(), kExitImplausible);
    return kExitImplausible;
  }
  if (warnings > 0) {
    std::fprintf(stderr,
                 "pfdm: %d of %zu frames with warnings (fit.json's quality "
                 "says why)\n",
                 warnings, fit.frames.size());
  }
  return 0;
}

// ED and ES volumes, and the ejection fraction where they are the
// cavity's; else what they are and how to say the points are the
// endocardium's.
void ReportVolumes(const FitAnalysis& analysis) {
  const EjectionFraction& ef = analysis.ejection_fraction;
  const bool cavity = analysis.volume_surface == "cavity";
  std::printf("%s volume: ED %.1f ml (frame %d), ES %.1f ml (frame %d)",
              analysis.volume_surface.c_str(), ef.edv_ml, ef.ed_frame,
              ef.esv_ml, ef.es_frame);
  if (ef.es_frame == ef.ed_frame) {
    std::printf("; no frame holds less than ED, so no ejection fraction\n");
  } else if (cavity) {
    std::printf(", ejection fraction %.2f\n", ef.ratio);
  } else {
    std::printf(
        "; not the cavity, so no ejection fraction (--surface endo if the "
        "points are the endocardium's)\n");
  }
}

}  // namespace

int RunFit() {
  if (FLAGS_out.empty()) throw InputError("fit needs --out DIR");
  const ModelConfig config = ModelConfigFromFlags();
  const FitOptions options = FitOptionsFromFlags();
  BasePlanesFromFlags("");  // Checks the flag before the fit.
  ParseRvInsertion(FitSettingsFromFlags().rv_insertion);  // Likewise.
  const VtkFormat vtk_format = VtkFormatFromFlags();
  // Before the minutes of work, not after them.
  CheckFitOutputFolder(FLAGS_out, FLAGS_points);
  const PointSequence points = PointsFromFlags();
  CheckOptionsAgainstPoints(options, points);
  const std::vector<BasePlane> planes = BasePlanesFromFlags(FLAGS_points);
  // The settings (fit.json) stay the user's; fit.json's model says where
  // the axis came from.
  FitOptions fit_options = options;
  AddLandmarkAxis(FLAGS_points, &fit_options);
  // gnuplot loads while the frames are fitted.
  SvgRendering plots;
  const SequenceFit fit = FitSequence(points, config, fit_options);
  CheckPlanesBelowApex(FLAGS_points, planes, fit);
  std::printf("wall: %s (%s)\n", fit.config.Solid() ? "solid" : "midwall",
              fit.wall_reason.c_str());
  const FitAnalysis analysis = AnalyzeFit(
      fit, planes,
      AnatomicalLayout(
          fit.ModelAt(0),
          RvInsertionFrom(FitSettingsFromFlags().rv_insertion, FLAGS_points)),
      ShowExtrapolatedFromFlags());
  std::printf("segments: %s (%s)\n",
              analysis.layout.anatomical ? "AHA, anatomical" : "not anatomical",
              analysis.layout.anchor.c_str());
  WriteFitOutputs(FLAGS_out, points, fit, analysis, options, vtk_format,
                  &plots);
  const int exit_code = ReportQuality(fit, analysis);
  ReportVolumes(analysis);
  std::printf(
      "wrote %s/fit.json, parameters.csv, parameters.svg, report.html, "
      "frame_*.vtk, frame_*.vtp, fit.pvd\n",
      FLAGS_out.c_str());
  return exit_code;
}

}  // namespace pfdm
