// pfdm fit: fits every frame and writes fit.json, plots, report and meshes.
#include <cstdio>

#include "pfdm/cli/commands.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/io/fit_output.h"
#include "pfdm/io/landmark_axis.h"
#include "pfdm/report/fit_analysis.h"
#include "pfdm/report/gnuplot.h"
#include "pfdm/util/error.h"

namespace pfdm {

int RunFit() {
  if (FLAGS_out.empty()) throw InputError("fit needs --out DIR");
  const ModelConfig config = ModelConfigFromFlags();
  const FitOptions options = FitOptionsFromFlags();
  BasePlanesFromFlags("");  // Checks the flag before the fit.
  const VtkFormat vtk_format = VtkFormatFromFlags();
  // Before the minutes of work, not after them.
  CheckFitOutputFolder(FLAGS_out, FLAGS_points);
  const PointSequence points = PointsFromFlags();
  // The settings (fit.json) stay the user's; fit.json's model says where
  // the axis came from.
  FitOptions fit_options = options;
  AddLandmarkAxis(FLAGS_points, &fit_options);
  // gnuplot loads while the frames are fitted.
  SvgRendering plots;
  const SequenceFit fit = FitSequence(points, config, fit_options);
  std::printf("wall: %s (%s)\n", fit.config.Solid() ? "solid" : "midwall",
              fit.wall_reason.c_str());
  WriteFitOutputs(FLAGS_out, points, fit,
                  AnalyzeFit(fit, BasePlanesFromFlags(FLAGS_points)), options,
                  vtk_format, &plots);
  for (const FrameFit& frame : fit.frames) {
    std::printf("frame %3d  points %5zu  rms %.3f mm  max %.3f mm  %s%s\n",
                frame.frame, frame.residuals.size(), frame.rms_mm,
                frame.max_distance_mm, frame.termination.c_str(),
                UnsettledNote(frame).c_str());
  }
  std::printf(
      "wrote %s/fit.json, parameters.csv, parameters.svg, report.html, "
      "frame_*.vtk, frame_*.vtp, fit.pvd\n",
      FLAGS_out.c_str());
  return 0;
}

}  // namespace pfdm
