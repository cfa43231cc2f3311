// The files `pfdm fit` writes: fit.json, parameters.csv, frame_NNN.vtk.
#ifndef PFDM_FIT_OUTPUT_H_
#define PFDM_FIT_OUTPUT_H_

#include <string>
#include <vector>

#include "pfdm/fitter.h"
#include "pfdm/model.h"
#include "pfdm/point_data.h"

namespace pfdm {

// One row per frame, function and knot: frame,function,knot,u,z_mm,value.
// Lengths (a0, a1..a3 as a0 a_i, b0, b2, offsets) in mm, tau in radians,
// eps and b1, b3 unitless; z_mm is the knot ring's axial position in the
// model frame.
std::string ParametersCsv(const std::vector<Model>& frames);

// Settings, model, gauge convention, per-frame errors and clinical summary.
std::string FitJson(const PointSequence& points, const SequenceFit& fit,
                    const FitOptions& options);

// The fitted surface (a u, v grid of triangles) and the data points as
// vertices, with point data u, v, is_data and the residual vectors.
std::string FrameVtk(const Model& model, const Frame& frame,
                     const FrameFit& fit);

// Writes all of the above into dir, each file atomically.
void WriteFitOutputs(const std::string& dir, const PointSequence& points,
                     const SequenceFit& fit, const FitOptions& options);

}  // namespace pfdm

#endif  // PFDM_FIT_OUTPUT_H_
