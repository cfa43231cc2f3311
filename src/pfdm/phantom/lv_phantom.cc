#include "pfdm/phantom/lv_phantom.h"

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "pfdm/util/error.h"

namespace pfdm {
namespace {

constexpr double kPi = 3.14159265358979323846;

// ED body positions of the tags, SPAMM-like (see the header).
std::vector<Eigen::Vector3d> PlaceTags(const LvShape& shape,
                                       const LvPhantomOptions& options) {
  std::mt19937 random(options.seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<Eigen::Vector3d> tags;
  tags.reserve(options.num_tags);
  for (int i = 0; i < options.num_tags; ++i) {
    const double w =
        options.tags == LvTagLayer::kWall ? -1.0 + 2.0 * uniform(random) : 0.0;
    double nu = 0.0;
    if (i % 2 == 0) {  // Short-axis plane: height uniform on this surface.
      const double apex = shape.ApexZ(w);
      nu =
          shape.NuAtHeight(apex + (shape.base_z() - apex) * uniform(random), w);
    } else {  // Long-axis plane: uniform along the meridian.
      nu = shape.NuAtArcFraction(uniform(random), w);
    }
    const double phi = -kPi + 2.0 * kPi * uniform(random);
    tags.push_back(shape.Position(nu, phi, w));
  }
  return tags;
}

// Moves each point of each frame, with probability outlier_fraction, by a
// distance uniform in the outlier range along a uniformly random direction
// (LvPhantomOptions), and says which in the truth.
class OutlierDraws {
 public:
  explicit OutlierDraws(const LvPhantomOptions& options)
      : options_(options), seed_{options.seed, 0x6f75746cu}, random_(seed_) {}

  // Whether the next point is an outlier; if so, adds its displacement
  // to *x.
  bool Move(Eigen::Vector3d* x) {
    // Every draw is made for every point, so that the fraction only
    // decides which displacements are applied.
    const double chance = uniform_(random_);
    Eigen::Vector3d direction(gaussian_(random_), gaussian_(random_),
                              gaussian_(random_));
    const double distance =
        options_.outlier_min_mm +
        (options_.outlier_max_mm - options_.outlier_min_mm) * uniform_(random_);
    if (!(chance < options_.outlier_fraction)) return false;
    *x += distance * direction.normalized();
    return true;
  }

 private:
  const LvPhantomOptions& options_;
  std::seed_seq seed_;
  std::mt19937 random_;
  std::uniform_real_distribution<double> uniform_{0.0, 1.0};
  std::normal_distribution<double> gaussian_{0.0, 1.0};
};

void CheckOptions(const LvPhantomOptions& options) {
  if (options.num_frames < 0 || options.num_tags < 1 ||
      !(options.noise_mm >= 0)) {
    throw InputError("lv phantom needs frames >= 1, tags >= 1 and noise >= 0");
  }
  if (!(options.outlier_fraction >= 0 && options.outlier_fraction <= 1 &&
        options.outlier_min_mm >= 0 &&
        options.outlier_max_mm >= options.outlier_min_mm &&
        options.outlier_max_mm <= 1000)) {
    throw InputError(
        "lv phantom needs an outlier fraction in [0, 1] and outlier "
        "distances 0 <= min <= max <= 1000 mm");
  }
  const LvShapeSize& size = options.shape;
  if (!(size.radius_mm > 0 && size.wall_mm > 0 &&
        size.wall_mm < size.radius_mm && size.base_nu_deg > 90 &&
        size.base_nu_deg < 180 &&
        size.length_mm / (1 - std::cos(size.base_nu_deg * kPi / 180)) >
            size.radius_mm)) {
    throw InputError(
        "lv phantom shape: needs 0 < wall < radius < a and "
        "90 < base_nu_deg < 180");
  }
}

}  // namespace

bool ParseLvTagLayer(const std::string& name, LvTagLayer* layer) {
  if (name == "midwall") {
    *layer = LvTagLayer::kMidwall;
  } else if (name == "wall") {
    *layer = LvTagLayer::kWall;
  } else {
    return false;
  }
  return true;
}

std::string LvTagLayerName(LvTagLayer layer) {
  return layer == LvTagLayer::kWall ? "wall" : "midwall";
}

Eigen::Vector3d LvWorldPoint(const LvShape& shape,
                             const LvDeformation& deformation,
                             const LvFrameMotion& motion,
                             const Eigen::Vector3d& ed_body) {
  return LvWorldPose() * RigidBodyMotion(shape, motion.rigid) *
         DeformedBodyPoint(deformation, MaterialPointAt(shape, ed_body),
                           motion.progress);
}

LvPhantom MakeLvPhantom(const LvPhantomOptions& options) {
  CheckOptions(options);
  LvPhantom phantom;
  phantom.options = options;
  if (phantom.options.num_frames == 0) {
    phantom.options.num_frames = DefaultFrameCount(options.kinematics);
  }
  const int num_frames = phantom.options.num_frames;
  const LvShape shape(options.shape);
  if (shape.ApexZ(-1.0) >= LvRingHeights().front() * shape.base_z()) {
    throw InputError(
        "lv phantom shape: the endocardial apex lies above "
        "the first truth ring");
  }
  const LvTruthMeter meter(shape);
  phantom.tag_material = PlaceTags(shape, options);
  phantom.points.source = "lv-phantom";

  // Noise from its own stream, so that it leaves the placement unchanged.
  std::seed_seq noise_seed{options.seed, 0x6e6f6973u};
  std::mt19937 random(noise_seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  OutlierDraws outliers(options);
  std::vector<LvMaterialPoint> tags, samples;
  for (const Eigen::Vector3d& x : phantom.tag_material) {
    tags.push_back(MaterialPointAt(shape, x));
  }
  for (const Eigen::Vector3d& x : meter.material()) {
    samples.push_back(MaterialPointAt(shape, x));
  }
  std::vector<Eigen::Vector3d> world0, world(samples.size());
  for (int t = 0; t < num_frames; ++t) {
    const LvFrameMotion motion =
        ScenarioMotion(options.kinematics, t, num_frames, options.breathing);
    const Eigen::Isometry3d world_from_body =
        LvWorldPose() * RigidBodyMotion(shape, motion.rigid);
    auto move = [&](const LvMaterialPoint& point) -> Eigen::Vector3d {
      return world_from_body *
             DeformedBodyPoint(options.deformation, point, motion.progress);
    };

    Frame frame;
    frame.index = t;
    std::vector<int> outlier_ids;
    for (int i = 0; i < options.num_tags; ++i) {
      Eigen::Vector3d x = move(tags[i]);
      for (int k = 0; k < 3; ++k) x[k] += options.noise_mm * noise(random);
      if (outliers.Move(&x)) outlier_ids.push_back(i);
      frame.points.push_back({i, x});
    }
    phantom.points.frames.push_back(std::move(frame));

    for (size_t i = 0; i < world.size(); ++i) {
      world[i] = move(samples[i]);
    }
    if (t == 0) world0 = world;
    LvFrameTruth truth = meter.Measure(world0, world);
    truth.frame = t;
    truth.progress = motion.progress;
    truth.rigid = motion.rigid;
    truth.world_from_body = world_from_body;
    truth.outlier_ids = std::move(outlier_ids);
    phantom.truth.push_back(std::move(truth));
  }
  return phantom;
}

}  // namespace pfdm
