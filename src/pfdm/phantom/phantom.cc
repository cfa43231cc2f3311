#include "pfdm/phantom/phantom.h"

#include <cmath>
#include <random>
#include <sstream>

#include "Eigen/Geometry"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

constexpr double kDegrees = 3.14159265358979323846 / 180.0;

// Truth at systolic progress p in [0, 1] for a knot at fraction b in [0, 1]
// from apex to base.
FunctionValues TruthAt(double a0, double p, double b) {
  FunctionValues f = DefaultFunctionValues();
  f[kA0] = a0;
  const double a1_ed = 0.26 + 0.08 * b;
  const double a2_ed = 0.24 + 0.07 * b * b;
  f[kA1] = a1_ed * (1.0 - 0.20 * p);
  f[kA2] = a2_ed * (1.0 - p * (0.20 - 0.10 * b * b));
  f[kA3] = 0.80 * (1.0 - 0.20 * p);
  f[kTau] = p * (-5.0 + 7.0 * b) * kDegrees;
  f[kE1o] = p * 1.5 * b * b;
  f[kE2o] = -p * 1.0 * b * (1.0 - b) * 4.0;
  return f;
}

}  // namespace

Phantom MakePhantom(const PhantomOptions& options) {
  const ModelConfig config = ModelConfig::Paper(options.num_knots);
  // Length a0 a3 (sin u_max - sin u_min) = 110 mm at end-diastole.
  const double a0 =
      110.0 / (0.80 * (std::sin(config.u_max) - std::sin(config.u_min)));
  const Eigen::Quaterniond rotation(
      Eigen::AngleAxisd(0.6, Eigen::Vector3d(0.3, -0.5, 0.8).normalized()));
  const Eigen::Vector3d center(12.0, -30.0, 45.0);

  Phantom phantom;
  phantom.points.source = "phantom";
  for (int t = 0; t < options.num_frames; ++t) {
    const double p = options.num_frames > 1
                         ? static_cast<double>(t) / (options.num_frames - 1)
                         : 0.0;
    Model model = Model::Uniform(config, TruthAt(a0, p, 0.0));
    for (int k = 0; k < config.num_knots; ++k) {
      model.state.knots[k] =
          TruthAt(a0, p, static_cast<double>(k) / (config.num_knots - 1));
    }
    model.state.center = {center.x(), center.y(), center.z()};
    model.state.quaternion = {rotation.w(), rotation.x(), rotation.y(),
                              rotation.z()};
    phantom.truth.push_back(model);
  }

  // Tags as SPAMM images give them: half from short-axis slices, evenly
  // spaced along the axis (sin u uniform: density by area), half from
  // long-axis planes through the axis (uniform along each meridian: u
  // uniform), which are what sample the apex.
  std::mt19937 random(options.seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, options.noise_mm);
  std::vector<std::pair<double, double>> tags;
  const double s_min = std::sin(config.u_min), s_max = std::sin(config.u_max);
  for (int i = 0; i < options.num_points; ++i) {
    const double u =
        i % 2 == 0
            ? std::asin(s_min + (s_max - s_min) * uniform(random))
            : config.u_min + (config.u_max - config.u_min) * uniform(random);
    const double v = -M_PI + 2.0 * M_PI * uniform(random);
    tags.emplace_back(u, v);
  }
  for (int t = 0; t < options.num_frames; ++t) {
    Frame frame;
    frame.index = t;
    for (int i = 0; i < options.num_points; ++i) {
      Eigen::Vector3d x =
          phantom.truth[t].WorldPoint(tags[i].first, tags[i].second);
      x += Eigen::Vector3d(noise(random), noise(random), noise(random));
      if (uniform(random) < options.outlier_fraction) {
        Eigen::Vector3d direction(noise(random), noise(random), noise(random));
        x += options.outlier_mm * direction.normalized();
      }
      frame.points.push_back({i, x});
    }
    phantom.points.frames.push_back(std::move(frame));
  }
  return phantom;
}

void CheckPhantomOptions(const PhantomOptions& options) {
  // Written so that NaN fails every test (it once wrote NaN rows).
  const auto check = [](const char* flag, double value, double low, double high,
                        const char* unit) {
    if (value >= low && value <= high) return;
    std::ostringstream text;
    text << "--" << flag << " must be between " << low << " and " << high
         << unit << ", got " << value;
    throw InputError(text.str());
  };
  check("frames", options.num_frames, 1, 1000, "");
  check("tags", options.num_points, 1, 1e6, "");
  check("noise", options.noise_mm, 0, 1000, " (mm)");
  check("outliers", options.outlier_fraction, 0, 1, " (a fraction)");
  // Each point takes some 40 bytes with its truth: 2e7 of them, 0.8 GB, is
  // already more than any fit of the phantom needs (1e6 tags over 20
  // frames); 1,000 frames of 1e6 tags would be 40 GB.
  const double total = double{1.0} * options.num_frames * options.num_points;
  if (total > kMaxPhantomPoints) {
    std::ostringstream text;
    text << "--frames times --tags must be at most " << kMaxPhantomPoints
         << " points, got " << options.num_frames << " x "
         << options.num_points;
    throw InputError(text.str());
  }
}

}  // namespace pfdm
