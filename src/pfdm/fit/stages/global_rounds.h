// The global model's correspondence rounds on one frame: the untracked
// points' closest material points are searched, the frame is solved for
// them (frame_problem.h), and again, until they settle or the rounds run out.
#ifndef PFDM_FIT_STAGES_GLOBAL_ROUNDS_H_
#define PFDM_FIT_STAGES_GLOBAL_ROUNDS_H_

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/fit/correspondence/frame_correspondence.h"
#include "pfdm/fit/correspondence/surface_grid.h"
#include "pfdm/fit/fit_options.h"
#include "pfdm/fit/problem/frame_problem.h"
#include "pfdm/fit/stages/frame_points.h"
#include "pfdm/fit/stages/round_acceleration.h"
#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/fit/stages/trajectory_recorder.h"
#include "pfdm/model/model.h"
#include "pfdm/solvers/solver.h"

namespace pfdm {

class GlobalRounds {
 public:
  // `prior` is the state the prior term pulls toward (the previous frame's,
  // or frame 0's for an untracked frame), `reference` frame 0's
  // (frame_problem.h says what of it the solve uses); both outlive the rounds,
  // and so do `options`, read at every solve (frame_fit.cc turns the loss on
  // between runs).  The rounds move *model and fill *fit's material points,
  // counts and trace.
  GlobalRounds(const FramePoints& frame, const ModelState& prior,
               const ModelState& reference, const FitOptions& options,
               const std::string& source, Model* model, FrameFit* fit);

  // The first search: on frame 0 of many points after a coarse solve on a
  // subset of them; in a solid, the tracked tags' depths ranked.
  void Start();
  // Solves and searches until the closest points settle; a solid's tracked
  // tags are re-ranked between solves instead.  With contour points only
  // (no tag among the untracked points) the rounds are accelerated and may run
  // to FitOptions:: max_accelerated_rounds; if they run out, the frame ends on
  // the round whose search moved the points least.  Throws InputError naming
  // the frame when a solve is unusable.
  void Run(TrajectoryRecorder* recorder);
  // A fresh search, after the model changed under the rounds (the wall).
  void Search();
  // With a robust loss, the ranks of tags across a solid's wall leave out
  // those farther than band_mm outside it (QuantileDepths); 0, the
  // default, ranks them all.  Held depths (frame 0's tags, kRerankRounds)
  // are ranked afresh in a new band.
  void set_rank_band_mm(double band_mm);
  // The searches' grid, kept from search to search (null, the default: a
  // grid per search); it outlives the rounds.
  void set_surface_grid(SurfaceGrid* grid) { grid_ = grid; }
  // A solid's tracked tags keep the depths they carry (held_depths.h)
  // instead of being ranked in this frame; before Start.
  void hold_depths() { hold_depths_ = true; }

  // The last solve's report.
  const SolverReport& report() const { return report_; }

 private:
  // A round's outcome: its search's move, model, material points, found
  // points, report and costs.
  struct Snapshot {
    double moved = std::numeric_limits<double>::infinity();
    ModelState state;
    std::vector<MaterialPoint> material;
    std::vector<Eigen::Vector3d> found, normals;
    SolverReport report;
    TermCosts costs;
  };

  void SolveCoarse();
  // A round's solve; a predictor takes one step only (PredictsRound).
  SolverReport SolveRound(TrajectoryRecorder* recorder, bool predictor);
  // Throws InputError naming the frame when the last solve is unusable.
  void CheckUsable() const;
  // Whether this round only brings the model near enough to rank a solid's
  // tags against it before the solve that counts.
  bool PredictsRound(int round) const;
  // Whether the rounds end after this solve.
  bool Settled(int round, int max_rounds);
  // The settled frame's last solve, on the settled closest points, without
  // the rounds' pull toward their start (global_rounds.cc, kSwingCosine).
  void SolveUnpulled(TrajectoryRecorder* recorder);
  // After a contour round that did not settle, its `change` at the probes:
  // whether it swung back against the last round's, which turns the
  // rounds' pull toward their start on (global_rounds.cc, kSwingCosine).
  void NoteSwing(const Eigen::VectorXd& change);
  // And the round is recorded and, past
  // FitOptions::max_correspondence_rounds, the next one starts from the
  // mix of the last rounds' solutions, its closest points searched there.
  void Accelerate(int round, Eigen::VectorXd change);
  // Keeps this round as the best so far when its search moved the points
  // least, or, after the last round, goes back to the best one.
  void KeepBest();
  void BackToBest();
  Snapshot Take() const;
  void Restore(Snapshot snapshot);
  // Sum of the untracked points' squared distances to their closest points.
  double SquaredDistanceToFound() const;
  // Searches the untracked points' closest material points and returns how
  // far (mm) the farthest one's model point moved from `now`, its model
  // point before the search (computed when not given).
  double UpdateClosest(std::vector<Eigen::Vector3d> now = {});

  const FramePoints& frame_;
  const ModelState& prior_;
  const ModelState& reference_;
  const FitOptions& options_;
  const std::string& source_;
  Model* model_;
  FrameFit* fit_;
  // What the last search found: the untracked points' model points (in
  // their order) on the model it searched, and the normals along which the
  // points pull, current until a solve moves the model.
  std::vector<Eigen::Vector3d> found_;
  std::vector<Eigen::Vector3d> normals_;
  bool normals_current_ = true;
  bool found_closest_ = false;  // Then searches start from the last.
  double moved_ = 0.0;          // By the last search.
  bool rerank_depths_ = false;
  bool hold_depths_ = false;
  DepthRanking ranking_;
  // Frame 0's tags through a solid's wall: ranked at the first searches,
  // then held at their depths (global_rounds.cc, kRerankRounds).
  bool ranks_tags_ = false;
  int ranked_searches_ = 0;
  // A solid's data end at one short-axis slice, which its walls' rims reach
  // (RimLift); decided on the model the rounds start from.  The last
  // solve's lift.
  bool top_is_slice_ = false;
  double rim_lift_ = 0.0;
  SurfaceGrid* grid_ = nullptr;
  SolverReport report_;
  // Frames whose untracked points are all contour points: the rounds are
  // accelerated (round_acceleration.h), the change of each measured at the
  // untracked points' first material points (every k-th of many).
  std::optional<RoundAcceleration> acceleration_;
  std::vector<MaterialPoint> probes_;
  // The last round's change at the probes; whether its rounds have swung
  // back, and each is pulled toward the state it starts from.  Only later
  // frames' contour rounds may be (no tag among the untracked points; not
  // frame 0 or the start's candidates: global_rounds.cc, kSwingCosine).
  Eigen::VectorXd last_change_;
  bool may_pull_ = false;
  bool pulled_ = false;
  // The round whose search moved the points least.
  std::optional<Snapshot> best_;
};

}  // namespace pfdm

#endif  // PFDM_FIT_STAGES_GLOBAL_ROUNDS_H_
