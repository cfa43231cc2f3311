// The files `pfdm fit` writes: fit.json (its contents: io/fit_json.h),
// parameters.csv, parameters.svg, report.html, frame_NNN.vtk and .vtp,
// fit.pvd.
#ifndef PFDM_IO_FIT_OUTPUT_H_
#define PFDM_IO_FIT_OUTPUT_H_

#include <string>
#include <vector>

#include "pfdm/fit/fit_options.h"
#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/io/vtk_output.h"
#include "pfdm/model/model.h"
#include "pfdm/report/fit_analysis.h"
#include "pfdm/report/gnuplot.h"
#include "pfdm/util/point_data.h"

namespace pfdm {

// Function f at u in the unit ParametersCsv reports it in.
double ReportedValue(const Model& model, int f, double u);
// That unit: "mm", "rad" or "1".
const char* ReportedUnit(int f);

// The u, v grid of the surface in the VTK files.
constexpr int kSurfaceRings = 33;
constexpr int kSurfaceMeridians = 48;

// One row per frame, function and knot: frame,function,knot,u,z_mm,value.
// Lengths (a0, a1..a3 as a0 a_i, b0, b2, offsets) in mm, tau in radians,
// eps and b1, b3 unitless; z_mm is the knot ring's axial position in the
// model frame.  With `fit`, a last column sd: the value's standard
// deviation in its unit (ReportedSd), 0 for an entry the gauge or the model
// holds, empty for a frame without a covariance (--uncertainty off).
std::string ParametersCsv(const std::vector<Model>& frames,
                          const SequenceFit* fit = nullptr);

// The standard deviation of ReportedValue(model, f, knot k's u) from the
// frame's covariance (a1..a3 as a0 a_i: to first order in a0 and a_i).
// a3's length along the axis also carries `length_variance`, the length's
// relative error that the highest points' noise and the fitted apex's put
// in (LengthVariance): frame 0 holds a0 where they set it, and neither its held
// a3 nor a tracked frame's, whose tags' material points frame 0 placed, takes
// it back (the radii do).  Without it a tracked frame's a3 held the noise-free
// fit in 75-85 % of the LV phantom's draws, with it 93-97 %.
double ReportedSd(const Model& model, const FrameCovariance& covariance, int f,
                  int k, double length_variance = 0.0);

// The fitted surface (a u, v grid of triangles) and the data points as
// vertices, with point data u, v, twist_deg (tau at u), is_data, the
// residual vectors and, for a fit with a robust loss, loss_weight (each
// data point's FrameFit::loss_weights, 1 on the surface).
VtkPolyData FramePolyData(const Model& model, const Frame& frame,
                          const FrameFit& fit);
std::string FrameVtk(const Model& model, const Frame& frame,
                     const FrameFit& fit);

// The file every folder pfdm writes a fit into holds, beside the set (not
// part of it: never removed).  pfdm batch writes only into case folders
// that hold it, or are new or empty, so never over files it did not make.
inline constexpr char kOutputMarker[] = ".pfdm-fit";
inline constexpr char kOutputMarkerText[] =
    "pfdm writes its fits into this folder; pfdm batch writes only into case "
    "folders that hold this file.\n";

// Whether a file name in an output folder is one of the output set
// (fit.json, parameters.csv, parameters.svg, report.html, fit.pvd,
// frame_NNN.vtk, frame_NNN.vtp) or a temporary of one (NAME.tmp.SUFFIX,
// SUFFIX letters, digits, '.' and '-').
bool IsFitOutputName(const std::string& name);

// Checks, before the minutes of a fit, that dir can take the output set:
// creates it, writes and removes a file in it, refuses an output name held
// by a folder or anything but a file, and refuses an input (input_path, ""
// for none) that is one of the outputs, which the write would remove.
// Throws InputError naming dir or the input.
void CheckFitOutputFolder(const std::string& dir,
                          const std::string& input_path);

// Writes all of the above into dir once everything has been computed, so
// that after any exit, a kill included, dir holds one complete set or none:
// kOutputMarker is made if absent, then fit.json, whose presence marks a
// complete set (pfdm batch resumes on it), is removed, then every other file
// and temporary of an older set (stale frames of a longer fit too), then the
// new files are written, each atomically, and fit.json last.  A failed write
// removes what it wrote. base_planes as for AnalyzeFit; vtk_output says
// which of each frame's .vtp (with fit.pvd) and .vtk are written, and how.
void WriteFitOutputs(const std::string& dir, const PointSequence& points,
                     const SequenceFit& fit, const FitOptions& options,
                     const std::vector<BasePlane>& base_planes = {},
                     const VtkOutput& vtk_output = VtkOutput());

// The same from the fit's analysis, made by the caller, with the plots
// rendered by `plots`, which the caller started (its Render not called):
// started before the fit, gnuplot's start-up (tens of ms, loading its
// libraries) overlaps the fit instead of adding to the outputs.
void WriteFitOutputs(const std::string& dir, const PointSequence& points,
                     const SequenceFit& fit, const FitAnalysis& analysis,
                     const FitOptions& options, const VtkOutput& vtk_output,
                     SvgRendering* plots, const std::string& slices_svg = "");

}  // namespace pfdm

#endif  // PFDM_IO_FIT_OUTPUT_H_
