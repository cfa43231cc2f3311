#include "pfdm/report/rv_insertion.h"

#include <algorithm>
#include <cmath>
#include <complex>

#include "pfdm/report/material_rings.h"

namespace pfdm {
namespace {

constexpr double kPi = 3.14159265358979323846;
// The coarse search's grid: rings equally spaced in sin u, meridians in v.
constexpr int kSearchRings = 40;
constexpr int kSearchMeridians = 72;
// The two insertions of one slice lie a septum apart (about 120 degrees);
// nearer than this they do not say which side the septum is on.
constexpr double kLeastPairAngle = 10.0 * kPi / 180.0;
// An insertion farther than this fraction of the model's apex-to-base
// length from its surface is not the LV's (a typo, another frame's
// coordinates): its angle would say nothing.
constexpr double kFarthestInsertion = 0.5;

double Wrapped(double angle) {
  return angle - 2.0 * kPi * std::floor((angle + kPi) / (2.0 * kPi));
}

double CircularMean(const std::vector<double>& angles) {
  std::complex<double> sum = 0.0;
  for (double a : angles) sum += std::polar(1.0, a);
  return std::arg(sum);
}

struct Located {
  MaterialLongitude at;
  bool anterior = false;
};

// Unlabelled points in pairs along the axis; in each, the anterior one is
// that from which the other lies clockwise seen from the base (decreasing
// v) the short way.  Empty when they do not pair.
std::vector<Located> ClassifyPairs(std::vector<MaterialLongitude> points,
                                   std::string* why) {
  if (points.size() % 2 != 0) {
    *why = std::to_string(points.size()) +
           " RV insertion points, not one anterior and one inferior per slice";
    return {};
  }
  std::sort(points.begin(), points.end(),
            [](const MaterialLongitude& a, const MaterialLongitude& b) {
              return a.height_fraction > b.height_fraction;
            });
  std::vector<Located> located;
  for (size_t i = 0; i + 1 < points.size(); i += 2) {
    const double turn = Wrapped(points[i + 1].v - points[i].v);
    if (std::abs(turn) < kLeastPairAngle) continue;  // Too close to tell.
    located.push_back({points[i], turn < 0});
    located.push_back({points[i + 1], turn > 0});
  }
  if (located.empty()) *why = "the RV insertion points' pairs lie together";
  return located;
}

std::vector<Located> Locate(const Model& reference,
                            const RvInsertion& insertion, std::string* why) {
  std::vector<Located> located;
  for (const auto& p : insertion.anterior) {
    located.push_back({NearestLongitude(reference, p), true});
  }
  for (const auto& p : insertion.inferior) {
    located.push_back({NearestLongitude(reference, p), false});
  }
  if (insertion.unlabelled.empty()) return located;
  std::vector<MaterialLongitude> points;
  for (const auto& p : insertion.unlabelled) {
    points.push_back(NearestLongitude(reference, p));
  }
  const std::vector<Located> pairs = ClassifyPairs(points, why);
  located.insert(located.end(), pairs.begin(), pairs.end());
  return located;
}

}  // namespace

MaterialLongitude NearestLongitude(const Model& reference,
                                   const Eigen::Vector3d& world) {
  const double s_min = std::sin(reference.config.u_min);
  const double s_max = std::sin(reference.config.u_max);
  // u within its range: asin(sin(u_max)) may pass it by a rounding, off the
  // local field's last row.
  auto u_of = [&](double s) {
    return std::clamp(std::asin(s), reference.config.u_min,
                      reference.config.u_max);
  };
  auto distance = [&](double s, double v) {
    return (reference.WorldPoint(u_of(s), v) - world).norm();
  };
  double best_s = s_min, best_v = 0.0, best = distance(s_min, 0.0);
  for (int i = 0; i <= kSearchRings; ++i) {
    const double s = s_min + (s_max - s_min) * i / kSearchRings;
    for (int j = 0; j < kSearchMeridians; ++j) {
      const double v = -kPi + 2.0 * kPi * j / kSearchMeridians;
      const double d = distance(s, v);
      if (d < best) best = d, best_s = s, best_v = v;
    }
  }
  // Pattern search from the grid's best, the steps halving.
  double ds = (s_max - s_min) / kSearchRings, dv = 2.0 * kPi / kSearchMeridians;
  for (int round = 0; round < 30; ++round, ds /= 2, dv /= 2) {
    for (bool moved = true; moved;) {
      moved = false;
      for (const auto& [step_s, step_v] :
           {std::pair{ds, 0.0}, {-ds, 0.0}, {0.0, dv}, {0.0, -dv}}) {
        const double s = std::clamp(best_s + step_s, s_min, s_max);
        const double d = distance(s, best_v + step_v);
        if (d < best) best = d, best_s = s, best_v += step_v, moved = true;
      }
    }
  }
  const double apex = RingHeight(reference, reference.config.u_min);
  const double base = RingHeight(reference, reference.config.u_max);
  return {Wrapped(best_v),
          (RingHeight(reference, u_of(best_s)) - apex) / (base - apex), best};
}

RegionLayout AnatomicalLayout(const Model& reference,
                              const std::optional<RvInsertion>& insertion,
                              RegionLayout layout) {
  if (!insertion) return layout;
  std::string why = "no RV insertion points";
  const std::vector<Located> located = Locate(reference, *insertion, &why);
  const double length = std::abs(RingHeight(reference, reference.config.u_max) -
                                 RingHeight(reference, reference.config.u_min));
  for (const Located& l : located) {
    if (l.at.distance_mm > kFarthestInsertion * length) {
      layout.anchor = insertion->source + ": a point lies " +
                      std::to_string(static_cast<int>(l.at.distance_mm)) +
                      " mm from frame 0's model, not on the LV";
      return layout;
    }
  }
  // The anchor from the basal and mid thirds' points if there are some.
  bool upper = false;
  for (const Located& l : located) {
    upper |= l.anterior && l.at.height_fraction >= 1.0 / 3.0;
  }
  std::vector<double> anterior, inferior;
  for (const Located& l : located) {
    if (upper && l.at.height_fraction < 1.0 / 3.0) continue;
    (l.anterior ? anterior : inferior).push_back(l.at.v);
  }
  if (anterior.empty()) {
    layout.anchor = insertion->source + ": " + why;
    return layout;
  }
  layout.anatomical = true;
  layout.anchor = insertion->source;
  layout.anchor_v = CircularMean(anterior);
  layout.anterior_points = static_cast<int>(anterior.size());
  layout.inferior_points = static_cast<int>(inferior.size());
  layout.direction = -1.0;
  if (!inferior.empty()) {
    layout.inferior_v = CircularMean(inferior);
    // Labelled insertions say which side the septum is on whatever the
    // frame's handedness; paired ones were labelled by it.
    layout.direction =
        Wrapped(layout.inferior_v - layout.anchor_v) < 0 ? -1.0 : 1.0;
  }
  return layout;
}

}  // namespace pfdm
