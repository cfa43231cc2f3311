// The wall (FitOptions::wall, docs/gauge.md "The wall"): whether the fit is
// a single surface or a solid, decided from the contours before frame 0 or
// from the tags' spread after its mid-wall fit; and, for a solid of tags,
// their noise taken out of the thickness at the end.
#ifndef PFDM_FIT_STAGES_WALL_STAGE_H_
#define PFDM_FIT_STAGES_WALL_STAGE_H_

#include <optional>
#include <string>
#include <vector>

#include "pfdm/fit/fit_options.h"
#include "pfdm/fit/stages/frame_points.h"
#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/model/model.h"
#include "pfdm/util/point_data.h"

namespace pfdm {

struct WallDecision {
  bool decided = false;
  std::string reason;                        // SequenceFit::wall_reason.
  WallLayer surface = WallLayer::kAnywhere;  // SequenceFit::surface.
};

// Before any fit: --surface declares one surface on its wall; contours of
// both walls make *config a solid; --wall midwall, data with neither tags
// nor both walls, or tracked points all named as one wall's (a mesh's
// surface column), a single surface (points of one wall name it).
// Undecided otherwise: tags through the wall are told from tags on one
// surface after frame 0's mid-wall fit (DecideWallFromTags).  Throws
// InputError when --wall solid meets data with neither or --surface, and
// when --surface names one wall and frame 0 has points of the other.
WallDecision DecideWallFromContours(const Frame& first, bool has_tags,
                                    const FitOptions& options,
                                    const std::string& source,
                                    ModelConfig* config);

// After frame 0's mid-wall rounds (converged: whether their last solve
// did), with the wall undecided: frame 0's tags spread across the wall by
// at least kMinWallSpreadMm, outliers left out (RobustWallSpreadMm), make
// the model a solid, of the thickness the tags inside the wall give
// (InsideTheWall), and so does --wall solid; the reason says what was
// measured.  Returns whether the model became a solid (the rounds must then
// run again).
bool DecideWallFromTags(const FramePoints& frame,
                        const std::vector<MaterialPoint>& material,
                        bool converged, WallModel wall, WallDecision* decision,
                        Model* model);

// The frame's global model: its fit without the local field.  The tags'
// noise is measured on its residuals, not on the fit's: the local field has
// nearly as many unknowns as 400 tags have coordinates and fits part of
// their noise (0.5 mm of it read 0.36-0.39 mm after the field, 0.48-0.50
// before, on the LV phantom's tags through the wall).
Model GlobalModelOf(const ModelConfig& config, const FrameFit& frame);

// What a frame's tags' noise is read from: each tag's residual, the
// model's misfit included (TangentialNoiseMm), or the differences of
// neighbouring tags' residuals, without its smooth part
// (NeighbourTangentialNoiseMm), which held depths' shrinkage needs.
enum class TagNoiseFrom { kResiduals, kNeighbours };

// The noise (mm per coordinate) of a tracked frame's tags, those of its
// points seen in more than one frame, across their wall normals on the
// frame's global model (the local field fits part of the noise); none
// without tags.  `robust` (a fit with a robust loss): measured robustly.
// `reference`, frame 0's global model: frame 0's share of the noise taken
// as stretched by the wall's motion since then (tangential_stretch.h); the
// share taken as frame 0's noise unchanged without it.
std::optional<double> FrameTagNoiseMm(
    const Model& global, const Frame& frame,
    const std::vector<MaterialPoint>& material,
    const FramesPerId& frames_per_id, bool robust = false,
    TagNoiseFrom from = TagNoiseFrom::kResiduals,
    const Model* reference = nullptr);

// Each tag's depth in *tracked_material, measured across frame 0's walls
// (measured_depths.h), shrunk to its expectation for noise of sigma_mm:
// ShrunkDepth(w, 2 sigma_mm / h), h `reference`'s (frame 0's global model,
// whose walls the contours place) at the tag's u.  Unshrunk, a measured
// depth's noise read every later wall thinner (regression toward the
// middle: on the LV phantom, 400 tags through the wall beside both walls'
// contours at ED and ES alone read thickening 1.5-5.5 % between them
// against 13.5, 11.1-15.6 shrunk; at ES 35.9-37.4 % against 40.6,
// 37.5-40.1 shrunk).
void ShrinkMeasuredDepths(const Model& reference, double sigma_mm,
                          TrackedMaterial* tracked_material);

// Each of frame 0's (`first`'s) tags in *tracked_material takes its held
// depth (HeldDepths) on `reference`, frame 0's global model, for noise of
// sigma_mm.
void HoldTagDepths(const Frame& first, const Model& reference, double sigma_mm,
                   TrackedMaterial* tracked_material);

// A solid's tags ranked across the wall widen a frame's h by their noise, a
// thin wall's more (DeconvolvedThickness): measures the noise on the
// tracked frames (FrameTagNoiseMm) and takes it out of the h of every
// frame that ranked them (frame 0 always; a tracked frame unless its
// depths were held, which are free of it; no frame whose contours placed
// the walls, measured_depths.h), then summarizes the frames again.
void TakeOutTagNoise(const PointSequence& sequence,
                     const FramesPerId& frames_per_id, SequenceFit* result,
                     bool robust = false);

}  // namespace pfdm

#endif  // PFDM_FIT_STAGES_WALL_STAGE_H_
