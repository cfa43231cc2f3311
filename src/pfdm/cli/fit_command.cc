// pfdm fit: fits every frame and writes fit.json, plots, report and meshes.
#include <cstdio>

#include "pfdm/cli/commands.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/io/fit_output.h"
#include "pfdm/io/landmark_axis.h"
#include "pfdm/io/mitral_valve_planes.h"
#include "pfdm/io/rv_insertion_source.h"
#include "pfdm/io/segmentation_overlay.h"
#include "pfdm/io/segmentation_source.h"
#include "pfdm/report/fit_analysis.h"
#include "pfdm/report/gnuplot.h"
#include "pfdm/report/report_text.h"
#include "pfdm/util/error.h"
#include "pfdm/util/verdict.h"
#include "pfdm/util/version.h"

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
  std::printf("%s volume: ED %s (frame %d), ES %s (frame %d)",
              analysis.volume_surface.c_str(),
              WithUnit(ef.edv_ml, 1, " ml").c_str(), ef.ed_frame,
              WithUnit(ef.esv_ml, 1, " ml").c_str(), ef.es_frame);
  if ((!Measured(ef.esv_ml) || !Measured(ef.edv_ml)) && ef.es_by_midwall) {
    std::printf(
        "; ED or end-systole (the least volume inside the mid-wall) is a "
        "frame with nothing that places the walls, so no ejection fraction "
        "(fit.json's not_measured.walls_unseen says which)\n");
  } else if (!Measured(ef.esv_ml) || !Measured(ef.edv_ml)) {
    std::printf(
        "; a frame's data span too little of the axis for its volume, so no "
        "ejection fraction (fit.json's verdicts say which)\n");
  } else if (ef.es_frame == ef.ed_frame) {
    std::printf("; no frame holds less than ED, so no ejection fraction\n");
  } else if (cavity) {
    std::printf(", ejection fraction %.2f%s\n", ef.ratio,
                ef.es_by_midwall ? " (ES the least volume inside the mid-wall: "
                                   "frames have no cavity)"
                                 : "");
  } else {
    std::printf(
        "; not the cavity, so no ejection fraction (--surface endo if the "
        "points are the endocardium's)\n");
  }
}

// What was read from the label map, and its misaligned slices as warnings.
void ReportSegmentation(const Segmentation& s) {
  const LabelVolume& v = s.volume;
  const MaskContours& c = s.contours;
  std::printf(
      "segmentation: %d slices x %d frames, %.2f x %.2f x %.2f mm (%s); "
      "apex at slice %d, frame 0's base at slice %d; RV insertion on %zu "
      "slices\n",
      v.nz, v.nt, v.Spacing(0), v.Spacing(1), v.Spacing(2), v.geometry.c_str(),
      c.apex_slice, c.base_slice.front(), c.rv_insertion.size() / 2);
  for (const std::string& warning : c.warnings) {
    std::fprintf(stderr, "pfdm: warning: %s: %s\n", v.source.c_str(),
                 warning.c_str());
  }
}

// The contours the reader left out (io/partial_rings.h), one line each.
void ReportLeftOut(const PointSequence& points) {
  for (const LeftOutContour& c : points.left_out) {
    std::printf(
        "left out: frame %d: %s (%d points covering %.0f of 360 degrees "
        "seen from the axis: its slice holds the outflow tract, beside the "
        "axis, not the ventricle round it)\n",
        c.frame, c.contour.c_str(), c.points, c.coverage_deg);
  }
}

// The points of --points, or the contours of --segmentation (its RV
// insertion then in *segmentation).
PointSequence InputPoints(std::optional<Segmentation>* segmentation) {
  if (FLAGS_segmentation.empty()) return PointsFromFlags();
  if (!FLAGS_points.empty()) {
    throw InputError("give --points or --segmentation, not both");
  }
  *segmentation = ReadSegmentation(FLAGS_segmentation, FLAGS_labels);
  ReportSegmentation(**segmentation);
  return (*segmentation)->contours.points;
}

std::optional<RvInsertion> InputRvInsertion(
    const std::optional<Segmentation>& segmentation) {
  const std::string flag = FitSettingsFromFlags().rv_insertion;
  if (!segmentation || !flag.empty()) {
    return RvInsertionFrom(flag, FLAGS_points);
  }
  return segmentation->rv_insertion;
}

}  // namespace

int RunFit() {
  if (FLAGS_out.empty()) throw InputError("fit needs --out DIR");
  const ModelConfig config = ModelConfigFromFlags();
  const FitOptions options = FitOptionsFromFlags();
  BasePlanesFromFlags("");  // Checks the flag before the fit.
  ParseRvInsertion(FitSettingsFromFlags().rv_insertion);  // Likewise.
  const VtkOutput vtk_output = VtkOutputFromFlags();
  // Before the minutes of work, not after them.
  CheckFitOutputFolder(FLAGS_out, FLAGS_segmentation.empty()
                                      ? FLAGS_points
                                      : FLAGS_segmentation);
  std::optional<Segmentation> segmentation;
  const PointSequence points = InputPoints(&segmentation);
  ReportLeftOut(points);
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
  FitAnalysis analysis = AnalyzeFit(
      fit, planes,
      AnatomicalLayout(fit.ModelAt(0), InputRvInsertion(segmentation)),
      ShowExtrapolatedFromFlags());
  if (segmentation) AttachSegmentation(*segmentation, &analysis);
  analysis.made_by = CommandLine();
  analysis.made_utc = UtcMinuteNow();
  std::printf("segments: %s (%s)\n",
              analysis.layout.anatomical ? "AHA, anatomical" : "not anatomical",
              analysis.layout.anchor.c_str());
  const std::string slices_svg =
      segmentation
          ? SegmentationOverlaySvg(segmentation->volume, segmentation->labels,
                                   segmentation->contours, analysis.models,
                                   analysis.ejection_fraction.es_frame)
          : "";
  WriteFitOutputs(FLAGS_out, points, fit, analysis, options, vtk_output, &plots,
                  slices_svg);
  const int exit_code = ReportQuality(fit, analysis);
  ReportVolumes(analysis);
  std::printf(
      "wrote %s/fit.json, parameters.csv, parameters.svg, report.html, %s\n",
      FLAGS_out.c_str(),
      vtk_output.files == VtkFiles::kVtp ? "frame_*.vtp, fit.pvd"
      : vtk_output.files == VtkFiles::kVtk
          ? "frame_*.vtk"
          : "frame_*.vtk, frame_*.vtp, fit.pvd");
  return exit_code;
}

}  // namespace pfdm
