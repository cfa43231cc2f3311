#include "pfdm/report/local_field_noise.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "Eigen/Core"
#include "pfdm/model/raised_top.h"
#include "pfdm/report/number_uncertainty.h"
#include "pfdm/util/parallel_for.h"

namespace pfdm {
namespace {

// Where Flatten puts the volume: the clinical fields come first.
size_t VolumeIndex() {
  ClinicalSummary c;
  const std::vector<double*> fields = ClinicalFields(&c);
  return std::find(fields.begin(), fields.end(), &c.volume_ml) - fields.begin();
}

// Frame t's numbers (Flatten's order) against the ED frame's samples.
Eigen::VectorXd MeasureOne(const FitAnalysis& analysis,
                           const std::vector<Model>& models, size_t ed,
                           const ReferenceSamples& samples, size_t t) {
  const std::vector<double> values =
      Flatten(MeasureFrame(models[ed], samples, analysis.regions, models[t],
                           VolumePlaneOf(analysis, t)));
  return Eigen::Map<const Eigen::VectorXd>(values.data(), values.size());
}

// The ejection fraction's (ratio, EDV, ESV) after the frames' numbers.
void AppendEjection(const FitAnalysis& analysis,
                    std::vector<Eigen::VectorXd>* out) {
  const EjectionFraction& ef = analysis.ejection_fraction;
  if (ef.ed_frame >= 0 && ef.es_frame >= 0 &&
      static_cast<size_t>(std::max(ef.ed_frame, ef.es_frame)) < out->size()) {
    const double edv = (*out)[ef.ed_frame][VolumeIndex()];
    const double esv = (*out)[ef.es_frame][VolumeIndex()];
    out->push_back(Eigen::Vector3d((edv - esv) / edv, edv, esv));
  }
}

// Every frame's numbers with these models, against the ED frame's, and the
// ejection fraction's last.
std::vector<Eigen::VectorXd> MeasureAll(const FitAnalysis& analysis,
                                        const std::vector<Model>& models,
                                        size_t ed) {
  const ReferenceSamples samples = SampleReference(models[ed], analysis.layout);
  std::vector<Eigen::VectorXd> out;
  for (size_t t = 0; t < models.size(); ++t) {
    out.push_back(MeasureOne(analysis, models, ed, samples, t));
  }
  AppendEjection(analysis, &out);
  return out;
}

// MeasureAll's, where only the `changed` frames' models differ from those
// that measured `at`: the others' numbers are at's, unless ED changed.
std::vector<Eigen::VectorXd> MeasureChanged(
    const FitAnalysis& analysis, const std::vector<Model>& models, size_t ed,
    const std::vector<bool>& changed, const std::vector<Eigen::VectorXd>& at) {
  if (changed[ed]) return MeasureAll(analysis, models, ed);
  const ReferenceSamples samples = SampleReference(models[ed], analysis.layout);
  std::vector<Eigen::VectorXd> out(at.begin(), at.begin() + models.size());
  for (size_t t = 0; t < models.size(); ++t) {
    if (changed[t]) out[t] = MeasureOne(analysis, models, ed, samples, t);
  }
  AppendEjection(analysis, &out);
  return out;
}

// `model` with `draw` added to its local field's values.
Model WithDraw(const Model& model, const std::vector<double>& draw) {
  Model out = model;
  out.state.local.AddCoefficients(draw);
  return out;
}

// The draws' mean shift from `at` and their variance, per number.
struct Moments {
  std::vector<Eigen::VectorXd> bias, variance;
};

Moments ZeroMoments(const std::vector<Eigen::VectorXd>& at) {
  Moments m;
  for (const Eigen::VectorXd& v : at) {
    m.bias.push_back(Eigen::VectorXd::Zero(v.size()));
    m.variance.push_back(Eigen::VectorXd::Zero(v.size()));
  }
  return m;
}

// The local field's draws: each frame's k-th added to its field.  The
// draws are measured on fit.threads threads and summed in their order, the
// same to the bit for any number of threads.
Moments SampleLocalField(const SequenceFit& fit, const FitAnalysis& analysis,
                         const std::vector<Eigen::VectorXd>& at, size_t draws) {
  const size_t ed = static_cast<size_t>(fit.ed_frame);
  std::vector<std::vector<Eigen::VectorXd>> measured(draws);
  ParallelFor(draws, fit.threads, [&](int, size_t k) {
    std::vector<Model> models;
    for (size_t t = 0; t < fit.frames.size(); ++t) {
      models.push_back(WithDraw(analysis.models[t],
                                fit.frames[t].covariance.local_noise[k]));
    }
    measured[k] = MeasureAll(analysis, models, ed);
  });
  Moments sum = ZeroMoments(at);  // Of the shifts and their squares.
  for (const std::vector<Eigen::VectorXd>& y : measured) {
    for (size_t i = 0; i < y.size(); ++i) {
      const Eigen::VectorXd shift = y[i] - at[i];
      sum.bias[i] += shift;
      sum.variance[i] += shift.cwiseProduct(shift);
    }
  }
  Moments m;
  const double n = static_cast<double>(draws);
  for (size_t i = 0; i < at.size(); ++i) {
    const Eigen::VectorXd mean = sum.bias[i] / n;
    m.bias.push_back(mean);
    m.variance.push_back(
        ((sum.variance[i] - n * mean.cwiseProduct(mean)) / (n - 1.0))
            .cwiseMax(0.0));
  }
  return m;
}

// Whether frame t's length moves with frame `source`'s length draws: frame
// 0's places the material points of frame 0 and of the tracked frames; an
// untracked later frame's (contours) holds its own base rim alone.
bool LengthMovesWith(size_t source, size_t t, const SequenceFit& fit) {
  if (source == 0) return t == 0 || fit.frames[t].tracked;
  return t == source;
}

// Frame `source`'s length draws, taken as linear: each number's derivative
// by the length's relative change (from one measurement with the frames it
// moves with their tops raised by the draws' sd, model/raised_top.h) times
// the draws' mean and sd.  Draws of different frames are of different
// points' noise: independent.
void AddLengthNoiseOf(size_t source, const SequenceFit& fit,
                      const FitAnalysis& analysis,
                      const std::vector<Eigen::VectorXd>& at, Moments* m) {
  const FrameCovariance& covariance = fit.frames[source].covariance;
  const double mean = covariance.LengthNoiseMean();
  const double variance = covariance.LengthNoiseVariance();
  const double step = std::sqrt(variance);
  if (!(step > 0.0)) return;
  std::vector<Model> models = analysis.models;
  std::vector<bool> raised(models.size(), false);
  for (size_t t = 0; t < models.size(); ++t) {
    raised[t] = LengthMovesWith(source, t, fit);
    if (raised[t]) models[t] = RaisedTop(models[t], step);
  }
  const std::vector<Eigen::VectorXd> y = MeasureChanged(
      analysis, models, static_cast<size_t>(fit.ed_frame), raised, at);
  for (size_t i = 0; i < y.size(); ++i) {
    const Eigen::VectorXd slope = (y[i] - at[i]) / step;
    m->bias[i] += mean * slope;
    m->variance[i] += variance * slope.cwiseProduct(slope);
  }
}

void AddLengthNoise(const SequenceFit& fit, const FitAnalysis& analysis,
                    const std::vector<Eigen::VectorXd>& at, Moments* m) {
  for (size_t source = 0; source < fit.frames.size(); ++source) {
    AddLengthNoiseOf(source, fit, analysis, at, m);
  }
}

// Whether some frame's length has a variance to add (AddLengthNoiseOf):
// its top's draws, or frame 0's apex.
bool HasLengthNoise(const SequenceFit& fit) {
  for (const FrameFit& frame : fit.frames) {
    if (frame.covariance.LengthNoiseVariance() > 0.0) return true;
  }
  return false;
}

Moments Sample(const SequenceFit& fit, const FitAnalysis& analysis,
               size_t local_draws) {
  const std::vector<Eigen::VectorXd> at =
      MeasureAll(analysis, analysis.models, static_cast<size_t>(fit.ed_frame));
  Moments m = local_draws >= 2
                  ? SampleLocalField(fit, analysis, at, local_draws)
                  : ZeroMoments(at);
  AddLengthNoise(fit, analysis, at, &m);
  return m;
}

// sd's frame t with `variance` added, and the bias in its layout, NaN
// where sd's is.
void StoreFrame(size_t t, const Eigen::VectorXd& variance,
                const Eigen::VectorXd& bias, NumberSd* sd, NumberSd* out) {
  FrameNumbers sds{sd->clinical[t], sd->region_motion[t], sd->strain[t]};
  std::vector<double> values = Flatten(sds);
  std::vector<double> shifts(values.size(), kNotMeasured);
  for (size_t i = 0; i < values.size(); ++i) {
    if (!Measured(values[i])) continue;
    values[i] = std::sqrt(values[i] * values[i] + variance[i]);
    shifts[i] = bias[i];
  }
  Unflatten(values.data(), &sds);
  FrameNumbers biases = sds;
  Unflatten(shifts.data(), &biases);
  sd->clinical[t] = sds.clinical;
  sd->region_motion[t] = sds.regions;
  sd->strain[t] = sds.strain;
  out->clinical[t] = biases.clinical;
  out->region_motion[t] = biases.regions;
  out->strain[t] = biases.strain;
}

void StoreEjection(const Eigen::VectorXd& variance, const Eigen::VectorXd& bias,
                   NumberSd* sd, NumberSd* out) {
  EjectionFraction& ef = sd->ejection_fraction;
  out->ejection_fraction = ef;
  double* sds[] = {&ef.ratio, &ef.edv_ml, &ef.esv_ml};
  double* shifts[] = {&out->ejection_fraction.ratio,
                      &out->ejection_fraction.edv_ml,
                      &out->ejection_fraction.esv_ml};
  for (int i = 0; i < 3; ++i) {
    if (!Measured(*sds[i])) {
      *shifts[i] = kNotMeasured;
      continue;
    }
    *sds[i] = std::sqrt(*sds[i] * *sds[i] + variance[i]);
    *shifts[i] = bias[i];
  }
}

// Every frame's local field draws' count, or 0 where some frame has none
// or another count.
size_t LocalDraws(const SequenceFit& fit) {
  const size_t draws = fit.frames[0].covariance.local_noise.size();
  for (const FrameFit& frame : fit.frames) {
    if (frame.covariance.local_noise.size() != draws) return 0;
  }
  return draws;
}

}  // namespace

NumberSd AddLocalFieldNoise(const SequenceFit& fit, const FitAnalysis& analysis,
                            NumberSd* sd) {
  NumberSd bias;
  if (!sd->computed || fit.frames.empty()) return bias;
  const size_t local_draws = LocalDraws(fit);
  if (local_draws < 2 && !HasLengthNoise(fit)) return bias;
  const Moments m = Sample(fit, analysis, local_draws);
  const size_t frames = fit.frames.size();
  bias.clinical.resize(frames);
  bias.region_motion.resize(frames);
  bias.strain.resize(frames);
  for (size_t t = 0; t < frames; ++t) {
    StoreFrame(t, m.variance[t], m.bias[t], sd, &bias);
  }
  if (m.bias.size() > frames) {
    StoreEjection(m.variance[frames], m.bias[frames], sd, &bias);
  }
  bias.computed = true;
  return bias;
}

}  // namespace pfdm
