// pfdm compare-solvers: the direct solve, the damped stepping and the
// explicit integrator on the same frames, with their convergence traces.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "commands.h"
#include "pfdm/atomic_file.h"
#include "pfdm/error.h"
#include "pfdm/gnuplot.h"
#include "pfdm/solver.h"

namespace pfdm {
namespace {

constexpr SolverKind kSolvers[] = {SolverKind::kDirect, SolverKind::kDamped,
                                   SolverKind::kIntegrator};

// The plotted frame: the first tracked one when there is one (the motion),
// else frame 0.
int PlottedFrame(const SequenceFit& fit) {
  return fit.frames.size() > 1 ? 1 : 0;
}

}  // namespace

int RunCompareSolvers() {
  if (FLAGS_out.empty()) throw InputError("compare-solvers needs --out DIR");
  const ModelConfig config = ModelConfigFromFlags();
  const FitOptions base = FitOptionsFromFlags();
  const PointSequence points = PointsFromFlags();

  std::ostringstream csv;
  csv.precision(10);
  csv << "solver,frame,iteration,pseudo_time,wall_seconds,cost,gradient_norm,"
         "rms_mm\n";
  std::vector<PlotData> plots;
  int plotted_frame = 0;
  for (SolverKind kind : kSolvers) {
    FitOptions options = base;
    options.solver.kind = kind;
    const SequenceFit fit = FitSequence(points, config, options);
    plotted_frame = PlottedFrame(fit);
    PlotData plot{SolverName(kind), {}};
    for (const FrameFit& frame : fit.frames) {
      const double n = static_cast<double>(frame.residuals.size());
      for (const SolverTracePoint& p : frame.trace) {
        csv << SolverName(kind) << ',' << frame.frame << ',' << p.iteration
            << ',' << p.pseudo_time << ',' << p.wall_seconds << ',' << p.cost
            << ',' << p.gradient_norm << ',' << std::sqrt(2.0 * p.cost / n)
            << '\n';
        if (frame.frame == PlottedFrame(fit)) {
          plot.rows.push_back({static_cast<double>(p.iteration),
                               p.wall_seconds, p.cost});
        }
      }
      std::printf("%-10s frame %3d  iterations %6d  %.3f s  rms %.4f mm  %s\n",
                  SolverName(kind), frame.frame, frame.iterations,
                  frame.solve_seconds, frame.rms_mm, frame.termination.c_str());
    }
    plots.push_back(std::move(plot));
  }

  // Plot the energy above the best rest point any solver reached, so that
  // the rates of approach show rather than the noise floor.
  double rest = INFINITY;
  for (const PlotData& plot : plots) {
    for (const auto& row : plot.rows) rest = std::min(rest, row[2]);
  }
  for (PlotData& plot : plots) {
    for (auto& row : plot.rows) row[2] = row[2] - rest + 1e-12 * rest;
  }
  std::string script =
      "set multiplot layout 1,2 title 'Convergence on the same residuals, "
      "frame " + std::to_string(plotted_frame) + "'\n"
      "set logscale y\nset ylabel 'E - E_{rest}'\nset key top right\n"
      "set logscale x\nset xlabel 'iteration / step'\nplot ";
  std::string by_time = "set xlabel 'wall time (s)'\nplot ";
  for (size_t i = 0; i < plots.size(); ++i) {
    const std::string sep = i + 1 < plots.size() ? ", " : "\n";
    script += "$" + plots[i].name + " using ($1+1):3 with lines lw 2 title '" +
              plots[i].name + "'" + sep;
    by_time += "$" + plots[i].name + " using 2:3 with lines lw 2 title '" +
               plots[i].name + "'" + sep;
  }
  script += by_time + "unset multiplot\n";

  EnsureDirectory(FLAGS_out);
  RenderSvg(plots, script, FLAGS_out + "/convergence.svg", 1200, 500);
  WriteFileAtomically(FLAGS_out + "/convergence.csv", csv.str());
  std::printf("wrote %s/convergence.csv and convergence.svg\n",
              FLAGS_out.c_str());
  return 0;
}

}  // namespace pfdm
