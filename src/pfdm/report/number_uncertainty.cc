#include "pfdm/report/number_uncertainty.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "Eigen/Geometry"
#include "pfdm/model/model_surface.h"
#include "pfdm/report/reference_rings.h"
#include "pfdm/report/tracked_response.h"
#include "pfdm/util/parallel_for.h"

namespace pfdm {

Model Nudged(const Model& model, const std::vector<CovarianceEntry>& entries,
             const Eigen::VectorXd& delta) {
  using Kind = CovarianceEntry::Kind;
  Model nudged = model;
  ModelState& state = nudged.state;
  Eigen::Vector3d rotation = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < entries.size(); ++i) {
    const CovarianceEntry& e = entries[i];
    switch (e.kind) {
      case Kind::kCenter:
        state.center[e.function] += delta[i];
        break;
      case Kind::kRotation:
        rotation[e.function] += delta[i];
        break;
      case Kind::kGlobal:
        state.globals[e.function] += delta[i];
        break;
      case Kind::kKnot:
        state.knots[e.knot][e.function] += delta[i];
        break;
    }
  }
  const double angle = rotation.norm();
  if (angle > 0.0) {
    const auto& q = state.quaternion;
    const Eigen::Quaterniond turned =
        Eigen::Quaterniond(Eigen::AngleAxisd(angle, rotation / angle)) *
        Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
    state.quaternion = {turned.w(), turned.x(), turned.y(), turned.z()};
  }
  return nudged;
}

MovedU MovedRange(const Model& model, const CovarianceEntry& entry) {
  MovedU range;
  range.rigid = entry.kind == CovarianceEntry::Kind::kCenter ||
                entry.kind == CovarianceEntry::Kind::kRotation;
  if (entry.kind != CovarianceEntry::Kind::kKnot) return range;
  const KnotGrid& grid = model.config.Grid();
  if (entry.knot > 0) range.low = grid.KnotU(entry.knot - 1);
  if (entry.knot + 1 < grid.num_knots()) {
    range.high = grid.KnotU(entry.knot + 1);
  }
  // RingHeight: a0 a3(u) sin u + e3o(u) at the apex and the rim.
  const bool end = entry.knot == 0 || entry.knot + 1 == grid.num_knots();
  range.heights = end && (entry.function == kA3 || entry.function == kE3o);
  return range;
}

Eigen::MatrixXd NumberJacobian(const Model& model,
                               const FrameCovariance& covariance,
                               const MovedNumbersOf& numbers) {
  return NumberJacobian(
      model, covariance, [&numbers] { return numbers; }, 1);
}

Eigen::MatrixXd NumberJacobian(const Model& model,
                               const FrameCovariance& covariance,
                               const MakeMovedNumbers& make, int threads) {
  const int n = static_cast<int>(covariance.entries.size());
  std::vector<int> varied;  // The entries with a variance to step by.
  for (int j = 0; j < n; ++j) {
    if (covariance.covariance(j, j) > 0.0) varied.push_back(j);
  }
  // Worker 0's measures `at` too; the others' are made on their own thread.
  std::vector<MovedNumbersOf> numbers(ParallelWorkers(varied.size(), threads));
  numbers[0] = make();
  const std::vector<double> at = numbers[0](model, MovedU());
  Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(at.size(), n);
  ParallelFor(varied.size(), threads, [&](int worker, size_t k) {
    if (!numbers[worker]) numbers[worker] = make();
    const int j = varied[k];
    const double step = kStepSd * std::sqrt(covariance.covariance(j, j));
    Eigen::VectorXd delta = Eigen::VectorXd::Zero(n);
    delta[j] = step;
    const MovedU range = MovedRange(model, covariance.entries[j]);
    const std::vector<double> up =
        numbers[worker](Nudged(model, covariance.entries, delta), range);
    const std::vector<double> down =
        numbers[worker](Nudged(model, covariance.entries, -delta), range);
    for (size_t i = 0; i < at.size(); ++i) {
      jacobian(i, j) = (up[i] - down[i]) / (2.0 * step);
    }
  });
  return jacobian;
}

Eigen::MatrixXd NumberJacobian(const Model& model,
                               const FrameCovariance& covariance,
                               const NumbersOf& numbers) {
  return NumberJacobian(
      model, covariance,
      [&](const Model& moved, const MovedU&) { return numbers(moved); });
}

Eigen::VectorXd Variances(const Eigen::MatrixXd& jacobian,
                          const Eigen::MatrixXd& covariance) {
  return (jacobian * covariance).cwiseProduct(jacobian).rowwise().sum();
}

std::vector<double> Flatten(const FrameNumbers& numbers) {
  FrameNumbers copy = numbers;
  std::vector<double> values;
  for (double* field : ClinicalFields(&copy.clinical)) {
    values.push_back(*field);
  }
  for (RegionMotion& motion : copy.regions) {
    for (double* field : RegionFields(&motion)) values.push_back(*field);
  }
  for (double* field : StrainFields(&copy.strain)) values.push_back(*field);
  return values;
}

std::vector<double> Flatten(const NumberSd& sd) {
  std::vector<double> values;
  for (size_t t = 0; t < sd.clinical.size(); ++t) {
    const std::vector<double> frame = Flatten(
        FrameNumbers{sd.clinical[t], sd.region_motion[t], sd.strain[t]});
    values.insert(values.end(), frame.begin(), frame.end());
  }
  const EjectionFraction& ef = sd.ejection_fraction;
  values.insert(values.end(), {ef.ratio, ef.edv_ml, ef.esv_ml});
  return values;
}

void Unflatten(const double* values, FrameNumbers* numbers) {
  for (double* field : ClinicalFields(&numbers->clinical)) *field = *values++;
  for (RegionMotion& motion : numbers->regions) {
    for (double* field : RegionFields(&motion)) *field = *values++;
  }
  for (double* field : StrainFields(&numbers->strain)) *field = *values++;
}

namespace {

// NaN where the analysis left a number out (or has no sd for it).
void MaskLike(const std::vector<double*>& values,
              const std::vector<double*>& sds) {
  for (size_t i = 0; i < values.size(); ++i) {
    if (!Measured(*values[i])) *sds[i] = kNotMeasured;
  }
}

// ClinicalSummary's fields that are no number with an sd.
void ClearNonNumbers(ClinicalSummary* sd) {
  sd->time_ms = kNotMeasured;
  sd->radial_ratio_x.clear();
  sd->radial_ratio_y.clear();
  sd->longitudinal_ratio.clear();
}

// The sds (square roots of `variance`, Flatten's order) of frame t, masked
// like the analysis's numbers.
void StoreFrame(const FitAnalysis& analysis, size_t t,
                const Eigen::VectorXd& variance, NumberSd* sd) {
  FrameNumbers numbers{analysis.clinical[t], analysis.region_motion[t],
                       analysis.strain[t]};
  FrameNumbers sds = numbers;
  const Eigen::VectorXd root = variance.cwiseMax(0.0).cwiseSqrt();
  Unflatten(root.data(), &sds);
  MaskLike(ClinicalFields(&numbers.clinical), ClinicalFields(&sds.clinical));
  ClearNonNumbers(&sds.clinical);
  for (size_t r = 0; r < sds.regions.size(); ++r) {
    MaskLike(RegionFields(&numbers.regions[r]), RegionFields(&sds.regions[r]));
    sds.regions[r].area_mm2 = kNotMeasured;
  }
  MaskLike(StrainFields(&numbers.strain), StrainFields(&sds.strain));
  sd->clinical[t] = sds.clinical;
  sd->region_motion[t] = sds.regions;
  sd->strain[t] = sds.strain;
}

// The rows of every frame's numbers' Jacobians: along ED's parameters
// (directly, and through the frame's response to them along the surface:
// TrackedResponse), along the frame's own (none at ED), and along ED's
// through held depths (empty elsewhere).
struct NumberJacobians {
  std::vector<Eigen::MatrixXd> along_ed, own, through_depths;
};

// The variance ED's noise puts through held depths twice: as the tracked
// frame's depth noise (FrameCovariance::depth_noise) and as ED's model
// moving the depths (TrackedResponse::through_wall); it is one error, the
// ED fit's residual, whose variance is the first less the second
// (tracked_response.h).  At most the first, per number.
Eigen::VectorXd SharedDepthVariance(const Eigen::MatrixXd& own,
                                    const Eigen::MatrixXd& through_depths,
                                    const FrameCovariance& frame,
                                    const Eigen::MatrixXd& ed_covariance) {
  if (through_depths.size() == 0 || frame.depth_noise.size() == 0) {
    return Eigen::VectorXd::Zero(own.rows());
  }
  return Variances(through_depths, ed_covariance)
      .cwiseMin(Variances(own, frame.depth_noise));
}

// The variances of numbers whose rows along ED's parameters are along_ed
// and along frame t's own are `own` (none at ED: no rows), through held
// depths `through_depths` (none elsewhere): ED's share, the frame's, less
// what both counted of ED's noise through the depths.
Eigen::VectorXd NumberVariances(const Eigen::MatrixXd& along_ed,
                                const Eigen::MatrixXd& own,
                                const Eigen::MatrixXd& through_depths,
                                const FrameCovariance& frame,
                                const Eigen::MatrixXd& ed_covariance) {
  Eigen::VectorXd total = Variances(along_ed, ed_covariance);
  if (own.rows() == total.size()) {
    total += Variances(own, frame.covariance) -
             SharedDepthVariance(own, through_depths, frame, ed_covariance);
  }
  return total;
}

// Where volume_ml sits in Flatten's order.
int VolumeRow() {
  ClinicalSummary c;
  const std::vector<double*> fields = ClinicalFields(&c);
  return static_cast<int>(
      std::find(fields.begin(), fields.end(), &c.volume_ml) - fields.begin());
}

// The ejection fraction's sd from the two volumes' rows: ESV's along ED's
// parameters (through ES's response) shares them with EDV's, so the ratio's
// variance is that of its derivatives' sum, not of two independent terms.
double EjectionRatioSd(const SequenceFit& fit, const EjectionFraction& ef,
                       const NumberJacobians& jacobians) {
  const double d_edv = ef.esv_ml / (ef.edv_ml * ef.edv_ml);
  const double d_esv = -1.0 / ef.edv_ml;
  const int row = VolumeRow();
  // ES's volume row of `rows` times d ratio / d ESV; none where ES has no
  // such rows.
  const auto es_row = [&](const Eigen::MatrixXd& rows) -> Eigen::MatrixXd {
    if (rows.rows() <= row) return {};
    return d_esv * rows.row(row);
  };
  const Eigen::MatrixXd along_ed =
      d_edv * jacobians.along_ed[ef.ed_frame].row(row) +
      d_esv * jacobians.along_ed[ef.es_frame].row(row);
  const double variance =
      NumberVariances(along_ed, es_row(jacobians.own[ef.es_frame]),
                      es_row(jacobians.through_depths[ef.es_frame]),
                      fit.frames[ef.es_frame].covariance,
                      fit.frames[fit.ed_frame].covariance.covariance)[0];
  return std::sqrt(std::max(variance, 0.0));
}

// The ejection fraction's sds: the volumes' are their frames'.
EjectionFraction EjectionSd(const SequenceFit& fit, const FitAnalysis& analysis,
                            const NumberJacobians& jacobians,
                            const NumberSd& sd) {
  const EjectionFraction& ef = analysis.ejection_fraction;
  EjectionFraction out = ef;
  out.edv_ml = sd.clinical[ef.ed_frame].volume_ml;
  // No ESV (a frame without a volume, EjectionFractionOf): none to have an
  // sd, whatever the least of the other volumes' is.
  out.esv_ml =
      Measured(ef.esv_ml) ? sd.clinical[ef.es_frame].volume_ml : kNotMeasured;
  out.ratio = kNotMeasured;
  if (Measured(ef.ratio) && ef.edv_ml > 0.0 && Measured(out.edv_ml) &&
      Measured(out.esv_ml)) {
    out.ratio =
        ef.es_frame == ef.ed_frame ? 0.0 : EjectionRatioSd(fit, ef, jacobians);
  }
  return out;
}

// Each frame's numbers' Jacobian with respect to its own parameters, ED
// held (none for ED).
std::vector<Eigen::MatrixXd> OwnJacobians(const SequenceFit& fit,
                                          const FitAnalysis& analysis) {
  const size_t ed = static_cast<size_t>(fit.ed_frame);
  const Model& ed_model = analysis.models[ed];
  const ReferenceSamples samples = SampleReference(ed_model, analysis.layout);
  std::vector<Eigen::MatrixXd> jacobian(fit.frames.size());
  // Whole frames to the threads where there are as many later frames as
  // threads; else each frame's steps spread over them.  A thread measures
  // a frame afresh (its own FrameMeasurer) before its first step of it.
  const int threads = std::max(fit.threads, 1);
  const bool by_frame = fit.frames.size() - 1 >= static_cast<size_t>(threads);
  ParallelFor(fit.frames.size(), by_frame ? threads : 1, [&](int, size_t t) {
    if (t == ed) return;
    const MakeMovedNumbers make = [&, t]() -> MovedNumbersOf {
      const auto frame = std::make_shared<const FrameMeasurer>(
          ed_model, samples, analysis.regions, analysis.models[t],
          VolumePlaneOf(analysis, t));
      return [frame](const Model& model, const MovedU& range) {
        return Flatten(frame->Moved(model, range));
      };
    };
    jacobian[t] = NumberJacobian(analysis.models[t], fit.frames[t].covariance,
                                 make, by_frame ? 1 : threads);
  });
  return jacobian;
}

}  // namespace

double EdSpin(const Model& ed, const Model& moved_ed) {
  // Exactly 0 for a step that did not turn ED, which R' R^T's round-off
  // would not give.
  if (moved_ed.state.quaternion == ed.state.quaternion) return 0.0;
  const Eigen::Vector3d axis = ed.Rotation().col(2);
  const Eigen::AngleAxisd turn(moved_ed.Rotation() * ed.Rotation().transpose());
  return turn.angle() * turn.axis().dot(axis);
}

Model SpunWith(const Model& ed, const Model& moved_ed, const Model& model) {
  const Eigen::Vector3d axis = ed.Rotation().col(2);
  const double spin = EdSpin(ed, moved_ed);
  if (spin == 0.0) return model;
  const Eigen::AngleAxisd about(spin, axis);
  const Eigen::Vector3d pivot(ed.state.center.data());
  Model spun = model;
  const Eigen::Vector3d center =
      pivot + about * (Eigen::Vector3d(model.state.center.data()) - pivot);
  spun.state.center = {center.x(), center.y(), center.z()};
  const auto& q = model.state.quaternion;
  const Eigen::Quaterniond turned =
      Eigen::Quaterniond(about) * Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
  spun.state.quaternion = {turned.w(), turned.x(), turned.y(), turned.z()};
  return spun;
}

namespace {

// Every frame's numbers (Flatten's, in frame order) for a step of ED's
// parameters, kept between steps: each frame's FrameMeasurer, and ED's
// samples, taken again only where a step of a knot moves ED and set back
// after each step (assigned, not copied anew: no allocation).
class EdStepMeasurer {
 public:
  EdStepMeasurer(const SequenceFit& fit, const FitAnalysis& analysis,
                 const ReferenceSamples& fitted_samples)
      : fit_(fit),
        analysis_(analysis),
        fitted_ed_(analysis.models[fit.ed_frame]),
        fitted_samples_(fitted_samples),
        samples_(fitted_samples) {
    for (size_t t = 0; t < fit.frames.size(); ++t) {
      frames_.emplace_back(fitted_ed_, fitted_samples, analysis.regions,
                           analysis.models[t], VolumePlaneOf(analysis, t));
    }
  }

  std::vector<double> operator()(const Model& ed_model, const MovedU& range) {
    // A step at an end knot that keeps the apex's and the rim's heights
    // keeps every row's level: only its span's rows move (all rows lie
    // strictly between u_min and u_max).
    const ModelConfig& config = ed_model.config;
    const bool keep_levels = !range.heights;
    ResampleReference(
        ed_model, analysis_.layout,
        keep_levels ? std::max(range.low, std::nextafter(config.u_min, 0.0))
                    : range.low,
        keep_levels ? std::min(range.high, std::nextafter(config.u_max, 0.0))
                    : range.high,
        &samples_);
    const bool spun = EdSpin(fitted_ed_, ed_model) != 0.0;
    ReferenceRings ed_rings(ed_model);
    std::vector<double> all;
    for (size_t t = 0; t < frames_.size(); ++t) {
      const std::vector<double> values =
          Flatten(MeasureFrameAt(t, ed_model, range, spun, &ed_rings));
      all.insert(all.end(), values.begin(), values.end());
    }
    samples_ = fitted_samples_;
    return all;
  }

 private:
  FrameNumbers MeasureFrameAt(size_t t, const Model& ed_model,
                              const MovedU& range, bool spun,
                              ReferenceRings* ed_rings) const {
    if (t == static_cast<size_t>(fit_.ed_frame)) {
      return frames_[t].Moved(ed_model, range, *ed_rings, samples_);
    }
    if (!spun) return frames_[t].Against(*ed_rings, samples_, range);
    return MeasureFrame(ed_model, samples_, analysis_.regions,
                        SpunWith(fitted_ed_, ed_model, analysis_.models[t]),
                        VolumePlaneOf(analysis_, t));
  }

  const SequenceFit& fit_;
  const FitAnalysis& analysis_;
  const Model& fitted_ed_;
  const ReferenceSamples& fitted_samples_;
  std::vector<FrameMeasurer> frames_;
  ReferenceSamples samples_;
};

// Every frame's numbers' Jacobian with respect to ED's parameters (rows in
// frame order), each frame's own parameters held; a spin of ED about its
// axis turns the other frames with it (SpunWith).  A step that does not
// spin ED leaves the other frames' models as they are
// (FrameMeasurer::Against).
Eigen::MatrixXd EdJacobian(const SequenceFit& fit,
                           const FitAnalysis& analysis) {
  const size_t ed = static_cast<size_t>(fit.ed_frame);
  const Model& fitted_ed = analysis.models[ed];
  const ReferenceSamples fitted_samples =
      SampleReference(fitted_ed, analysis.layout);
  const MakeMovedNumbers make = [&]() -> MovedNumbersOf {
    const auto measurer =
        std::make_shared<EdStepMeasurer>(fit, analysis, fitted_samples);
    return [measurer](const Model& ed_model, const MovedU& range) {
      return (*measurer)(ed_model, range);
    };
  };
  return NumberJacobian(fitted_ed, fit.frames[ed].covariance, make,
                        fit.threads);
}

// Each tracked frame's response to ED's parameters (tracked_response.h),
// empty where none.
std::vector<TrackedResponse> Responses(const SequenceFit& fit) {
  std::vector<TrackedResponse> responses(fit.frames.size());
  ParallelFor(fit.frames.size(), std::max(fit.threads, 1), [&](int, size_t t) {
    responses[t] = MeasureTrackedResponse(fit, t);
  });
  return responses;
}

}  // namespace

NumberSd PropagateUncertainty(const SequenceFit& fit,
                              const FitAnalysis& analysis) {
  NumberSd sd;
  if (fit.frames.empty() || fit.ed_frame < 0 ||
      static_cast<size_t>(fit.ed_frame) >= fit.frames.size()) {
    return sd;
  }
  for (const FrameFit& frame : fit.frames) {
    if (!frame.covariance.computed) return sd;
  }
  NumberJacobians jacobians{{}, OwnJacobians(fit, analysis), {}};
  const Eigen::MatrixXd from_ed = EdJacobian(fit, analysis);
  const std::vector<TrackedResponse> responses = Responses(fit);
  const size_t frames = fit.frames.size();
  const size_t size = from_ed.rows() / frames;
  const Eigen::MatrixXd& ed_covariance =
      fit.frames[fit.ed_frame].covariance.covariance;
  sd.clinical.resize(frames);
  sd.region_motion.resize(frames);
  sd.strain.resize(frames);
  for (size_t t = 0; t < frames; ++t) {
    // A number of frame t moves with ED's parameters directly and through
    // frame t's fit, which follows ED's (TrackedResponse).
    const Eigen::MatrixXd& own = jacobians.own[t];
    Eigen::MatrixXd along_ed = from_ed.middleRows(t * size, size);
    const TrackedResponse& response = responses[t];
    const bool follows = own.rows() == along_ed.rows() && !response.Empty() &&
                         response.along_surface.rows() == own.cols() &&
                         response.along_surface.cols() == along_ed.cols();
    Eigen::MatrixXd through_depths;
    if (follows) {
      along_ed += own * response.along_surface;
      if (response.through_wall.size() > 0) {
        through_depths = own * response.through_wall;
      }
    }
    StoreFrame(analysis, t,
               NumberVariances(along_ed, own, through_depths,
                               fit.frames[t].covariance, ed_covariance),
               &sd);
    jacobians.along_ed.push_back(std::move(along_ed));
    jacobians.through_depths.push_back(std::move(through_depths));
  }
  sd.ejection_fraction = EjectionSd(fit, analysis, jacobians, sd);
  sd.computed = true;
  return sd;
}

}  // namespace pfdm
