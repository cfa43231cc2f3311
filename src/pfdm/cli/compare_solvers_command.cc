// pfdm compare-solvers: the direct solve, the damped stepping and the
// explicit integrator on the same frames, with their convergence traces.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <sstream>

#include "pfdm/cli/commands.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/io/fit_output.h"
#include "pfdm/report/gnuplot.h"
#include "pfdm/solvers/solver.h"
#include "pfdm/util/atomic_file.h"
#include "pfdm/util/error.h"

DEFINE_int32(trajectory_per_decade, 10,
             "compare-solvers: model states written to trajectory.csv per "
             "decade of iterations (log-spaced, plus first and last), 1 to "
             "1000");

namespace pfdm {
namespace {

constexpr SolverKind kSolvers[] = {SolverKind::kDirect, SolverKind::kDamped,
                                   SolverKind::kIntegrator};

// Rows "iteration + 1, wall seconds, energy above the lowest energy any
// solver reached on the frame" for the log-log plot, about 100 a decade of
// iterations (the integrator's tens of thousands would bloat the SVG);
// rows at that lowest energy have no place on a log scale.
PlotData ExcessEnergy(SolverKind kind, const FrameFit& frame, double lowest) {
  PlotData plot{SolverName(kind), {}};
  double next = 0.0;
  for (size_t i = 0; i < frame.trace.size(); ++i) {
    const SolverTracePoint& p = frame.trace[i];
    const double excess = p.cost - lowest;
    const double x = p.iteration + 1.0;
    if (excess > 0.0 && (x >= next || i + 1 == frame.trace.size())) {
      plot.rows.push_back({x, std::max(p.wall_seconds, 1e-6), excess});
      next = x * 1.023;
    }
  }
  if (plot.rows.empty()) plot.rows.push_back({1.0, 1e-6, 1e-300});
  return plot;
}

// Rows solver,frame,iteration,pseudo_time,function,knot,value (units as in
// parameters.csv) for every function the model does not fix, at the
// recorded points of each solver's path.
std::string TrajectoryCsv(const ModelConfig& config,
                          const std::map<SolverKind, SequenceFit>& fits) {
  std::ostringstream csv;
  csv.precision(12);
  csv << "solver,frame,iteration,pseudo_time,function,knot,value\n";
  const KnotGrid grid = config.Grid();
  for (const auto& [kind, fit] : fits) {
    for (const FrameFit& frame : fit.frames) {
      for (const TrajectoryPoint& point : frame.trajectory) {
        const Model model{config, point.state};
        for (int f = 0; f < kNumFunctions; ++f) {
          if (config.modes[f] == FunctionMode::kFixed) continue;
          for (int k = 0; k < grid.num_knots(); ++k) {
            csv << SolverName(kind) << ',' << frame.frame << ','
                << point.iteration << ',' << point.pseudo_time << ','
                << FunctionName(f) << ',' << k << ','
                << ReportedValue(model, f, grid.KnotU(k)) << '\n';
          }
        }
      }
    }
  }
  return csv.str();
}

std::string PlotScript(const std::vector<PlotData>& plots, int frame) {
  std::string by_iteration, by_time;
  for (size_t i = 0; i < plots.size(); ++i) {
    const std::string block = "$" + plots[i].name;
    const std::string style =
        " with linespoints pt 7 ps 0.4 lw 2 title '" + plots[i].name + "'";
    const std::string sep = i + 1 < plots.size() ? ", " : "\n";
    by_iteration += block + " using 1:3" + style + sep;
    by_time += block + " using 2:3" + style + sep;
  }
  return "set multiplot layout 1,2 title 'Frame " + std::to_string(frame) +
         ": energy above the lowest reached, same residuals'\n"
         "set logscale xy\nset format y '10^{%L}'\nset grid\n"
         "set ylabel 'E - E_{min}'\nset key top right\n"
         "set xlabel 'iteration / step + 1'\nplot " +
         by_iteration + "set xlabel 'wall time (s)'\nplot " + by_time +
         "unset multiplot\n";
}

}  // namespace

int RunCompareSolvers() {
  if (FLAGS_out.empty()) throw InputError("compare-solvers needs --out DIR");
  CheckFitOutputFolder(FLAGS_out, "");  // Before the fits, not after them.
  const ModelConfig config = ModelConfigFromFlags();
  // Every solver runs: their settings all apply.
  FitOptions base = FitOptionsForEverySolver(FitSettingsFromFlags());
  if (FLAGS_trajectory_per_decade < 1 || FLAGS_trajectory_per_decade > 1000) {
    throw InputError(
        "--trajectory_per_decade must be between 1 and 1000, got " +
        std::to_string(FLAGS_trajectory_per_decade));
  }
  base.trajectory_per_decade = FLAGS_trajectory_per_decade;
  const PointSequence points = PointsFromFlags();
  CheckOptionsAgainstPoints(base, points);

  std::printf("integrator: %s, damping %s\n",
              IntegratorName(base.solver.integrator),
              DampingName(base.solver.damping));
  std::map<SolverKind, SequenceFit> fits;
  for (SolverKind kind : kSolvers) {
    FitOptions options = base;
    options.solver.kind = kind;
    fits[kind] = FitSequence(points, config, options);
  }

  std::ostringstream csv;
  csv.precision(12);
  csv << "solver,frame,iteration,pseudo_time,wall_seconds,cost,gradient_norm,"
         "rms_mm\n";
  std::map<SolverKind, double> seconds, iterations;
  for (SolverKind kind : kSolvers) {
    for (const FrameFit& frame : fits[kind].frames) {
      // sqrt(2 E / N): the RMS data residual when the regularizers' share of
      // E is small, as it is at a fitted frame.
      const double n = static_cast<double>(frame.residuals.size());
      for (const SolverTracePoint& p : frame.trace) {
        csv << SolverName(kind) << ',' << frame.frame << ',' << p.iteration
            << ',' << p.pseudo_time << ',' << p.wall_seconds << ',' << p.cost
            << ',' << p.gradient_norm << ',' << std::sqrt(2.0 * p.cost / n)
            << '\n';
      }
      std::printf(
          "%-10s frame %3d  iterations %6d  %8.3f s  rms %.6f mm  %s%s\n",
          SolverName(kind), frame.frame, frame.iterations, frame.solve_seconds,
          frame.rms_mm, frame.termination.c_str(),
          UnsettledNote(frame).c_str());
      seconds[kind] += frame.solve_seconds;
      iterations[kind] += frame.iterations;
    }
  }
  for (SolverKind kind : kSolvers) {
    std::printf(
        "%-10s all frames: %8.0f iterations (%.1fx direct), %.3f s "
        "(%.1fx direct)\n",
        SolverName(kind), iterations[kind],
        iterations[kind] / std::max(1.0, iterations[SolverKind::kDirect]),
        seconds[kind], seconds[kind] / seconds[SolverKind::kDirect]);
  }

  // The first tracked frame when there is one: the motion, one solve.
  const size_t plotted = points.frames.size() > 1 ? 1 : 0;
  double lowest = std::numeric_limits<double>::infinity();
  for (SolverKind kind : kSolvers) {
    for (const SolverTracePoint& p : fits[kind].frames[plotted].trace) {
      lowest = std::min(lowest, p.cost);
    }
  }
  std::vector<PlotData> plots;
  for (SolverKind kind : kSolvers) {
    plots.push_back(ExcessEnergy(kind, fits[kind].frames[plotted], lowest));
  }

  EnsureDirectory(FLAGS_out);
  RenderSvg(plots,
            PlotScript(plots, fits[SolverKind::kDirect].frames[plotted].frame),
            FLAGS_out + "/convergence.svg", 1200, 500);
  WriteFileAtomically(FLAGS_out + "/convergence.csv", csv.str());
  WriteFileAtomically(FLAGS_out + "/trajectory.csv",
                      TrajectoryCsv(config, fits));
  std::printf("wrote %s/convergence.csv, trajectory.csv and convergence.svg\n",
              FLAGS_out.c_str());
  return 0;
}

}  // namespace pfdm
