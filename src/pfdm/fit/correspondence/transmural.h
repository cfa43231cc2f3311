// Where tags sit across the wall (the solid model's w, model/transmural.h),
// and whether data say anything about the wall's thickness at all.
#ifndef PFDM_FIT_CORRESPONDENCE_TRANSMURAL_H_
#define PFDM_FIT_CORRESPONDENCE_TRANSMURAL_H_

#include <string>
#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/model/model.h"

namespace pfdm {

// --wall: a mid-wall surface, a solid, or whichever the data support
// (FitSequence says which it chose and why).
enum class WallModel { kAuto, kMidwall, kSolid };
// "auto", "midwall" or "solid"; throws InputError otherwise.
WallModel WallModelFromName(const std::string& name);
const char* WallModelName(WallModel model);

// A uniform spread of tags across the wall thinner than this (mm, as
// WallSpreadMm measures it) is read as tags on one surface plus noise: a
// wall is thicker (the LV's 4 mm at a thin apex to 15 mm), localization
// noise of 1 mm per coordinate reads 3.5 mm.
constexpr double kMinWallSpreadMm = 4.0;

// Signed distance (mm, + outward) of each point from the mid-wall, along
// the surface normal at its material point's (u, v), and, when
// midwall_points is given, the mid-wall's points there.
std::vector<double> MidwallDistances(
    const Model& model, const std::vector<Eigen::Vector3d>& points,
    const std::vector<MaterialPoint>& material,
    std::vector<Eigen::Vector3d>* midwall_points = nullptr);

// The thickness of the wall the points fill, read from how much each
// point's distance differs from that of its nearest neighbour along the
// mid-wall (midwall_points: MidwallDistances'): sqrt(6 mean (d_i -
// d_j)^2), which is h for points spread uniformly through a wall of
// thickness h and about 2.4 sigma for points on one surface with noise of
// sigma mm.  Neighbours, not the plain spread, so that where the surface
// misses a shape (a valve, an outflow tract) its points, which all miss it
// alike, do not read as a wall.  Neighbours are sought among at most
// 16,384 of the points (every m-th), and the mean is over every k-th of
// those's pair, at most 4,096 of them.
double WallSpreadMm(const std::vector<Eigen::Vector3d>& midwall_points,
                    const std::vector<double>& distances);

// A tag localized 5-10 mm off (a tracker that took the next stripe's) must
// not read as a wall.  A tag is an outlier when its distance departs from
// the median of its kOutlierNeighbours nearest tags' (along the mid-wall,
// as WallSpreadMm's neighbours, so that a shape the surface misses is no
// outlier) by more than kOutlierScales robust standard deviations of those
// departures (1.4826 times their median absolute value), and by more than
// kMinOutlierMm.  Four, not the usual 2.5-3, so that data without outliers
// keep every tag: tags on one surface with Gaussian noise lose 0.006 % of
// them (none of 2,000), and tags through a wall, whose departures are short
// tailed (a uniform's reach 1.35 such deviations; the LV phantom's, with
// the wall thinning toward the apex and the neighbours' median noisy, 2.8),
// none.  So among tags through a wall the fence is wide (12.6 mm on the LV
// phantom's 10 mm wall) and most outliers stay: they cannot make a wall of
// one surface there; the solid's start leaves out more (InsideTheWall).
constexpr int kOutlierNeighbours = 8;
constexpr double kOutlierScales = 4.0;
// Nearly noise-free points (mesh vertices, tags simulated without noise)
// depart by the fit's local misses only, which noise would hide: of
// biv-me's 1,572 LV mesh vertices (fitted at 0.8 mm RMS) 65 depart by more
// than 1 mm, 37 by more than 2.  No tag within 2 mm of its neighbours is an
// outlier; outliers are farther off, and such departures alone cannot
// spread tags 4 mm.
constexpr double kMinOutlierMm = 2.0;

// WallSpreadMm measured on the tags that are not outliers, sought among
// the tags WallSpreadMm takes its neighbours from: every tag up to 16,384
// of them, else every step-th.
struct RobustWallSpread {
  double spread_mm = 0.0;    // WallSpreadMm of the inliers.
  size_t step = 1;           // Tag k * step is the k-th examined.
  std::vector<bool> inlier;  // Per examined tag.
  size_t outliers = 0;       // Examined tags left out.
  double fence_mm = 0.0;     // Largest departure of an inlier allowed.
};

// Each tag's distance less the median of its kOutlierNeighbours nearest
// tags' along the mid-wall (taken among the same tags WallSpreadMm takes
// them from).
std::vector<double> NeighbourDepartures(
    const std::vector<Eigen::Vector3d>& midwall_points,
    const std::vector<double>& distances);

// The outliers (as above) left out, the spread of the rest.
RobustWallSpread RobustWallSpreadMm(
    const std::vector<Eigen::Vector3d>& midwall_points,
    const std::vector<double>& distances);

// Whether each tag (not only each examined one) lies within the spread's
// fence of its neighbours: a solid's start leaves the others out.
std::vector<bool> TagInliers(const RobustWallSpread& spread,
                             const std::vector<Eigen::Vector3d>& midwall_points,
                             const std::vector<double>& distances);

// The entries of `values` whose `keep` is set, in order.
template <typename T>
std::vector<T> KeptEntries(const std::vector<T>& values,
                           const std::vector<bool>& keep) {
  std::vector<T> kept;
  kept.reserve(values.size());
  for (size_t i = 0; i < values.size(); ++i) {
    if (keep[i]) kept.push_back(values[i]);
  }
  return kept;
}

// w of tags spread through the wall.  Tags sample the wall uniformly across
// its thickness (SPAMM tag intersections do; the wall's curvature puts a
// few percent more of them outside the mid-wall), so a tag's w is 2 q - 1,
// q its distance's quantile among the tags of its band of latitude (tags
// sorted by u, bands of a sixteenth of them, at least kMinBand).  Ranks, not
// distances, so that no wall thickness is assumed: the fit then finds h.
constexpr int kMinBand = 24;
std::vector<double> QuantileDepths(const std::vector<double>& u,
                                   const std::vector<double>& distances);
// The same with only the `ranked` tags ranked, each among the ranked tags
// of its band; the others take -1 or +1, the side of the mid-wall they lie
// on.  With a robust loss, tags outside the wall (WithinWall) are left out:
// ranked among the others, 5 % of outliers at 5-10 mm spread a 10 mm wall's
// ranks and thickened it.
std::vector<double> QuantileDepths(const std::vector<double>& u,
                                   const std::vector<double>& distances,
                                   const std::vector<bool>& ranked);

// The same ranks taken among each tag's nearest ranked tags along the
// mid-wall (midwall_points: MidwallDistances'), kDepthNeighbourhoods'
// share of them and at least kMinBand, instead of its band of latitude.
// Why: a band is a whole ring, so where one sector of it moves unlike the
// rest (a hypokinetic segment stays out while the ring contracts) its tags
// took the band's outer ranks, the depth absorbed the sector's motion and
// the local field saw none (the LV phantom's lesion through the wall read
// 20.6 % radial contraction, as its neighbours, against 15.9 % true).  A
// neighbourhood moves as one; its ranks hold where the wall's centre and
// thickness vary from one segment to the next.
constexpr size_t kDepthNeighbourhoods = 128;
std::vector<double> NeighbourhoodDepths(
    const std::vector<Eigen::Vector3d>& midwall_points,
    const std::vector<double>& distances, const std::vector<bool>& ranked);

// Whether each distance (MidwallDistances') lies within the wall of the
// model (a solid) at its material point's (u, v), widened by band_mm on
// either side.
std::vector<bool> WithinWall(const Model& model,
                             const std::vector<MaterialPoint>& material,
                             const std::vector<double>& distances,
                             double band_mm);

// Which tags lie in the wall their band of latitude (QuantileDepths')
// fills: within kWallFenceIqr interquartile ranges of the band's median
// distance.  Tags uniform through a wall reach one such range from it (h / 2
// each side), noise a little more (the LV phantom's tags through the wall,
// 0.5 mm noise: 1.77 at most); two leave half a wall beyond each surface
// (5 mm where it is 10 mm thick, 2 mm at a 4 mm apex), so that tags
// localized that far off do not widen the solid the fit starts from.  For
// tags through the wall only: on one surface with Gaussian noise the fence
// is 2.7 sigma.
constexpr double kWallFenceIqr = 2.0;
std::vector<bool> InsideTheWall(const std::vector<double>& u,
                                const std::vector<double>& distances);

// sigma from squared lengths each `scale` sigma^2 times a chi-squared of 2
// degrees of freedom (mean 2, median 2 ln 2): sqrt(mean / (2 scale)), or
// robust sqrt(median / (2 ln 2 scale)); 0 for none.  Reorders *squares.
double SigmaFromChiSquared2(std::vector<double>* squares, double scale,
                            bool robust);

// Localization noise (mm per coordinate, isotropic) of tracked tags, from
// their residuals across the normal of their layer: each of the two
// tangential directions carries this frame's noise and frame 0's (through
// the tag's (u, v)), so sigma^2 = mean |r - (r . n) n|^2 / 4.  Model error
// counts as noise here.  0 for no tags.  `robust` (a fit with a robust
// loss) takes the median of |r - (r . n) n|^2 instead: each tangential
// direction's residual is Gaussian with variance 2 sigma^2, their squared
// length 2 sigma^2 times a chi-squared of 2 degrees of freedom, whose
// median is 2 ln 2, so sigma^2 = median / (4 ln 2), which outliers barely
// move (the mean took 5 % of them at 5-10 mm for noise of 1.04 mm, not
// 0.46, and the thickness lost what they added).  Given each material
// tag's stretch_squared since frame 0 (tangential_stretch.h; indexed like
// `which`), frame 0's share is taken as stretched: |r_t|^2 carries
// sigma^2 (2 + |F|^2), and is scaled by 4 over that.
double TangentialNoiseMm(const Model& model,
                         const std::vector<Eigen::Vector3d>& residuals,
                         const std::vector<MaterialPoint>& material,
                         const std::vector<size_t>& which, bool robust = false,
                         const std::vector<double>* stretch_squared = nullptr);

// The thickness of a wall of tags ranked across it, their noise taken out:
// ranks of distances with noise sigma widen a wall of thickness h to
// h_obs = h + 6 sigma^2 / h (the least-squares slope of uniform plus
// Gaussian distances on their own quantiles is three times their Gini
// mean difference, h / 3 + 2 sigma^2 / h for small sigma), so
// h = (h_obs + sqrt(h_obs^2 - 24 sigma^2)) / 2, and h_obs / 2 where the
// root would be imaginary.  `squeezed`: the frame's depth profile had its
// cubic term free (the squeeze, model/transmural.h), whose endpoints follow
// the noise's soft tails further out than a straight line's: h_obs = h (1 +
// g(sigma / h)), g(x) = x^2 (19.77 - 62.11 x + 85.48 x^2) (the cubic
// least-squares fit of uniform plus Gaussian distances on their own
// quantiles, within 0.8 % of it for sigma <= h / 5; 20 sigma^2 / h for
// small sigma, against the line's 6), inverted by fixed-point iteration.
double DeconvolvedThickness(double h_obs, double sigma, bool squeezed = false);

// The thickness (mm) the distances imply at those depths: twice the
// least-squares slope of distance on w.
double ThicknessFromDepths(const std::vector<double>& distances,
                           const std::vector<double>& depths);

}  // namespace pfdm

#endif  // PFDM_FIT_CORRESPONDENCE_TRANSMURAL_H_
