#include "pfdm/phantom/lv_phantom.h"

#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "pfdm/phantom/lv_contours.h"
#include "pfdm/phantom/lv_slices.h"
#include "pfdm/util/angles.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

// The mid-ventricular segment: 40 mm of the 95 mm mid-wall, from 28 mm
// above its apex pole (22.6 mm radius) to past the equator (26.9 mm).
constexpr LvHeights kMidventricular{0.30, 0.72};
// A full short-axis stack's first and last planes: 4.75 mm above the apex
// pole (the apical slice, 21 mm across at the mid-wall) to 9.5 mm below
// the base plane.
constexpr LvHeights kFullStack{0.05, 0.90};

// A tag's w: uniform through the wall, drawn from `random` then only (the
// other layers' tags keep the draws they had before the endocardium's
// were added); -1 on the endocardium, 0 on the mid-wall, 1 on the
// epicardium.
double TagDepth(LvTagLayer layer, std::mt19937* random) {
  switch (layer) {
    case LvTagLayer::kWall:
      return -1.0 +
             2.0 * std::uniform_real_distribution<double>(0.0, 1.0)(*random);
    case LvTagLayer::kEndocardium:
      return -1.0;
    case LvTagLayer::kEpicardium:
      return 1.0;
    case LvTagLayer::kMidwall:
      break;
  }
  return 0.0;
}

// ED body positions of the tags, SPAMM-like (see the header).
std::vector<Eigen::Vector3d> PlaceTags(const LvShape& shape,
                                       const LvPhantomOptions& options) {
  std::mt19937 random(options.seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const LvHeights band = LvRegionHeights(options.region);
  const bool full = options.region == LvRegion::kFull;
  const double low_z = band.low * shape.base_z();
  const double high_z = band.high * shape.base_z();
  std::vector<Eigen::Vector3d> tags;
  tags.reserve(options.num_tags);
  for (int i = 0; i < options.num_tags; ++i) {
    const double w = TagDepth(options.tags, &random);
    double nu = 0.0;
    if (i % 2 == 0) {  // Short-axis plane: height uniform on this surface.
      const double low = full ? shape.ApexZ(w) : low_z;
      nu = shape.NuAtHeight(low + (high_z - low) * uniform(random), w);
    } else {  // Long-axis plane: uniform along the meridian (in the band).
      double z = 0.0;
      do {
        nu = shape.NuAtArcFraction(uniform(random), w);
        z = shape.Position(nu, 0.0, w).z();
      } while (!full && (z < low_z || z > high_z));
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
      !(options.noise_mm >= 0) || options.num_slices < 0) {
    throw InputError(
        "lv phantom needs frames >= 1, tags >= 1, noise >= 0 and slices >= 0");
  }
  if (options.sampling == LvSampling::kSaxSlices &&
      options.law != LvThickeningLaw::kDesigned) {
    throw InputError("lv phantom sax-slices: the designed thickening law only");
  }
  if (!(options.outlier_fraction >= 0 && options.outlier_fraction <= 1 &&
        options.outlier_min_mm >= 0 &&
        options.outlier_max_mm >= options.outlier_min_mm &&
        options.outlier_max_mm <= 1000)) {
    throw InputError(
        "lv phantom needs an outlier fraction in [0, 1] and outlier "
        "distances 0 <= min <= max <= 1000 mm");
  }
}

// The shape, checked: a shell the phantom's truth can measure.
LvShape CheckedShape(const LvShapeSize& size) {
  if (!(size.radius_mm > 0 && size.wall_mm > 0 &&
        size.wall_mm < size.radius_mm && size.base_nu_deg > 90 &&
        size.base_nu_deg < 180 &&
        size.length_mm / (1 - std::cos(size.base_nu_deg * kPi / 180)) >
            size.radius_mm)) {
    throw InputError(
        "lv phantom shape: needs 0 < wall < radius < a and "
        "90 < base_nu_deg < 180");
  }
  const LvShape shape(size);
  if (shape.ApexZ(-1.0) >= LvRingHeights().front() * shape.base_z()) {
    throw InputError(
        "lv phantom shape: the endocardial apex lies above "
        "the first truth ring");
  }
  return shape;
}

// The short-axis image planes, fixed where frame 0 puts them.
Eigen::Isometry3d EdWorldFromBody(const LvShape& shape,
                                  const LvPhantomOptions& options,
                                  int num_frames) {
  return LvWorldPose() *
         RigidBodyMotion(shape, ScenarioMotion(options.kinematics, 0,
                                               num_frames, options.breathing)
                                    .rigid);
}

std::vector<LvImagePlane> ImagePlanes(const LvShape& shape,
                                      const LvPhantomOptions& options,
                                      int num_frames) {
  const Eigen::Isometry3d world_from_body =
      EdWorldFromBody(shape, options, num_frames);
  std::vector<LvImagePlane> planes;
  for (double h : LvSliceHeights(options)) {
    planes.push_back(ShortAxisPlane(world_from_body, h * shape.base_z()));
  }
  return planes;
}

// Points a contour (one plane, one surface): num_tags shared evenly.
int ContourPoints(const LvPhantomOptions& options, size_t num_planes) {
  const int contours = static_cast<int>(num_planes) *
                       (options.tags == LvTagLayer::kWall ? 2 : 1);
  if (options.num_tags < contours) {
    throw InputError("lv phantom sax-slices: " +
                     std::to_string(options.num_tags) + " points for " +
                     std::to_string(contours) + " contours; at least one each");
  }
  return options.num_tags / contours;
}

LvLawRadii LawRadii(const LvShape& shape) {
  return {shape.size().radius_mm, shape.size().wall_mm};
}

// ED body positions of tags in the cylinder: height, longitude and (through
// the wall) w uniform.
std::vector<Eigen::Vector3d> PlaceCylinderTags(
    const LvCylinder& cylinder, const LvPhantomOptions& options) {
  std::mt19937 random(options.seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<Eigen::Vector3d> tags;
  for (int i = 0; i < options.num_tags; ++i) {
    const double w = TagDepth(options.tags, &random);
    const double h =
        cylinder.low + (cylinder.high - cylinder.low) * uniform(random);
    tags.push_back(cylinder.Position(h, -kPi + 2.0 * kPi * uniform(random), w));
  }
  return tags;
}

// MakeLvPhantom of the cylinder: tags as the shell's (noise, outliers), the
// truth analytic.
LvPhantom MakeCylinderPhantom(const LvPhantomOptions& options,
                              LvPhantom phantom) {
  if (options.sampling != LvSampling::kTags || options.deformation.lesion) {
    throw InputError(
        "lv phantom cylinder: tags only (no --sampling sax-slices, no "
        "--lesion)");
  }
  phantom.options.region = LvRegion::kMidventricular;
  const LvHeights band = LvRegionHeights(LvRegion::kMidventricular);
  const LvCylinder cylinder = CylinderOf(options.shape, band.low, band.high);
  const LvShape shape(options.shape);  // Its base_z centres the rigid motion.
  phantom.tag_material = PlaceCylinderTags(cylinder, options);
  const int num_frames = phantom.options.num_frames;
  const LvFrameMotion ed =
      ScenarioMotion(options.kinematics, 0, num_frames, options.breathing);
  auto world_from_body = [&](const LvFrameMotion& motion) {
    return LvWorldPose() * RigidBodyMotion(shape, motion.rigid);
  };
  auto insertion = [&](double phi_deg) {
    return world_from_body(ed) *
           cylinder.Position(kLvInsertionHeight, phi_deg * kPi / 180, 0.0);
  };
  phantom.rv_anterior = insertion(kLvAnteriorInsertionDeg);
  phantom.rv_inferior = insertion(kLvInferiorInsertionDeg);
  std::seed_seq noise_seed{options.seed, 0x6e6f6973u};
  std::mt19937 random(noise_seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  OutlierDraws outliers(options);
  for (int t = 0; t < num_frames; ++t) {
    const LvFrameMotion motion =
        ScenarioMotion(options.kinematics, t, num_frames, options.breathing);
    const Eigen::Isometry3d pose = world_from_body(motion);
    Frame frame;
    frame.index = t;
    std::vector<int> outlier_ids;
    for (int i = 0; i < options.num_tags; ++i) {
      Eigen::Vector3d x =
          pose *
          DeformedBodyPoint(options.deformation,
                            cylinder.MaterialPoint(phantom.tag_material[i]),
                            motion.progress, options.law, cylinder.LawRadii());
      for (int k = 0; k < 3; ++k) x[k] += options.noise_mm * noise(random);
      if (outliers.Move(&x)) outlier_ids.push_back(i);
      frame.points.push_back({i, x});
    }
    phantom.points.frames.push_back(std::move(frame));
    LvFrameTruth truth = CylinderTruth(cylinder, options.deformation,
                                       options.law, motion.progress);
    truth.frame = t;
    truth.rigid = motion.rigid;
    truth.world_from_body = pose;
    truth.outlier_ids = std::move(outlier_ids);
    phantom.truth.push_back(std::move(truth));
  }
  return phantom;
}

}  // namespace

LvHeights LvRegionHeights(LvRegion region) {
  return region == LvRegion::kMidventricular ? kMidventricular : LvHeights();
}

std::vector<double> LvSliceHeights(const LvPhantomOptions& options) {
  const bool mid = options.region == LvRegion::kMidventricular;
  const LvHeights stack = mid ? kMidventricular : kFullStack;
  const int n = options.num_slices > 0 ? options.num_slices : mid ? 3 : 9;
  std::vector<double> heights;
  for (int k = 0; k < n; ++k) {
    heights.push_back(n == 1 ? 0.5 * (stack.low + stack.high)
                             : stack.low +
                                   (stack.high - stack.low) * k / (n - 1.0));
  }
  return heights;
}

bool ParseLvRegion(const std::string& name, LvRegion* region) {
  if (name == "full") {
    *region = LvRegion::kFull;
  } else if (name == "midventricular") {
    *region = LvRegion::kMidventricular;
  } else {
    return false;
  }
  return true;
}

std::string LvRegionName(LvRegion region) {
  return region == LvRegion::kMidventricular ? "midventricular" : "full";
}

bool ParseLvSampling(const std::string& name, LvSampling* sampling) {
  if (name == "tags") {
    *sampling = LvSampling::kTags;
  } else if (name == "sax-slices") {
    *sampling = LvSampling::kSaxSlices;
  } else {
    return false;
  }
  return true;
}

std::string LvSamplingName(LvSampling sampling) {
  return sampling == LvSampling::kSaxSlices ? "sax-slices" : "tags";
}

bool ParseLvTagLayer(const std::string& name, LvTagLayer* layer) {
  if (name == "midwall") {
    *layer = LvTagLayer::kMidwall;
  } else if (name == "wall") {
    *layer = LvTagLayer::kWall;
  } else if (name == "endo") {
    *layer = LvTagLayer::kEndocardium;
  } else if (name == "epi") {
    *layer = LvTagLayer::kEpicardium;
  } else {
    return false;
  }
  return true;
}

std::string LvTagLayerName(LvTagLayer layer) {
  switch (layer) {
    case LvTagLayer::kWall:
      return "wall";
    case LvTagLayer::kEndocardium:
      return "endo";
    case LvTagLayer::kEpicardium:
      return "epi";
    case LvTagLayer::kMidwall:
      break;
  }
  return "midwall";
}

Eigen::Vector3d LvWorldPoint(const LvShape& shape,
                             const LvDeformation& deformation,
                             const LvFrameMotion& motion,
                             const Eigen::Vector3d& ed_body,
                             LvThickeningLaw law) {
  return LvWorldPose() * RigidBodyMotion(shape, motion.rigid) *
         DeformedBodyPoint(deformation, MaterialPointAt(shape, ed_body),
                           motion.progress, law, LawRadii(shape));
}

LvPhantom MakeLvPhantom(const LvPhantomOptions& options) {
  CheckOptions(options);
  LvPhantom phantom;
  phantom.options = options;
  if (phantom.options.num_frames == 0) {
    phantom.options.num_frames = DefaultFrameCount(options.kinematics);
  }
  const int num_frames = phantom.options.num_frames;
  phantom.points.source = "lv-phantom";
  if (options.geometry == LvGeometry::kCylinder) {
    return MakeCylinderPhantom(options, std::move(phantom));
  }
  const LvShape shape = CheckedShape(options.shape);
  const LvTruthMeter meter(shape);
  const bool slices = options.sampling == LvSampling::kSaxSlices;
  if (!slices) phantom.tag_material = PlaceTags(shape, options);
  const std::vector<LvImagePlane> planes =
      slices ? ImagePlanes(shape, options, num_frames)
             : std::vector<LvImagePlane>();
  const int per_contour =
      slices
          ? ContourPoints(options, planes.size() + options.num_long_axis_planes)
          : 0;
  const LvFrameMotion ed =
      ScenarioMotion(options.kinematics, 0, num_frames, options.breathing);
  const double insertion_nu =
      shape.NuAtHeight(kLvInsertionHeight * shape.base_z(), 0.0);
  auto insertion = [&](double phi_deg) {
    return LvWorldPoint(shape, options.deformation, ed,
                        shape.Position(insertion_nu, phi_deg * kPi / 180, 0.0),
                        options.law);
  };
  phantom.rv_anterior = insertion(kLvAnteriorInsertionDeg);
  phantom.rv_inferior = insertion(kLvInferiorInsertionDeg);

  // Noise from its own stream, so that it leaves the placement unchanged.
  std::seed_seq noise_seed{options.seed, 0x6e6f6973u};
  std::mt19937 random(noise_seed);
  std::mt19937 placement(options.seed);  // The slices' longitudes.
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
      return world_from_body * DeformedBodyPoint(options.deformation, point,
                                                 motion.progress, options.law,
                                                 LawRadii(shape));
    };

    Frame frame;
    frame.index = t;
    std::vector<int> outlier_ids;
    for (int i = 0; i < static_cast<int>(tags.size()); ++i) {
      Eigen::Vector3d x = move(tags[i]);
      for (int k = 0; k < 3; ++k) x[k] += options.noise_mm * noise(random);
      if (outliers.Move(&x)) outlier_ids.push_back(i);
      frame.points.push_back({i, x});
    }
    if (slices) {
      const std::int64_t first_id =
          static_cast<std::int64_t>(t) * options.num_tags;
      frame.points = SliceContours(shape, options, motion, planes, per_contour,
                                   first_id, &placement, &random);
      const std::vector<DataPoint> long_axis = LongAxisContours(
          shape, options, motion, EdWorldFromBody(shape, options, num_frames),
          per_contour,
          first_id + static_cast<std::int64_t>(frame.points.size()), &placement,
          &random);
      frame.points.insert(frame.points.end(), long_axis.begin(),
                          long_axis.end());
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
