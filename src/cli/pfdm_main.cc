// pfdm: fits deformable models with parameter functions to LV point data.
#include <cstdio>
#include <exception>
#include <filesystem>
#include <sstream>
#include <string>

#include "gflags/gflags.h"
#include "pfdm/error.h"
#include "pfdm/fit_output.h"
#include "pfdm/fitter.h"
#include "pfdm/phantom.h"
#include "pfdm/point_reader.h"
#include "pfdm/point_writer.h"
#include "pfdm/atomic_file.h"

DEFINE_string(points, "", "fit: input points, a frame,id,x,y,z CSV, or a biv-me "
              "GPFile_*.txt or a folder of them");
DEFINE_string(format, "auto", "fit: csv, gpfile or auto (by name)");
DEFINE_string(contours, "lv-endo", "fit: GPFile contour types to keep, "
              "comma-separated; lv-endo and lv-epi are aliases");
DEFINE_string(out, "", "fit: output folder; simulate: output CSV");
DEFINE_string(model, "paper", "fit: paper or superellipsoid");
DEFINE_int32(knots, 17, "fit: knots per parameter function");
DEFINE_double(smoothness, 1.0, "fit: smoothness weight (per knot's data)");
DEFINE_double(prior, 0.001, "fit: pull toward the previous frame");
DEFINE_string(loss, "none", "fit: none, huber or cauchy");
DEFINE_double(loss_scale, 1.0, "fit: robust loss scale, mm");
DEFINE_int32(threads, 1, "fit: Ceres threads");
DEFINE_string(apex, "", "fit: optional apex hint x,y,z (mm), with --base");
DEFINE_string(base, "", "fit: optional base-centre hint x,y,z (mm)");
DEFINE_int32(frames, 5, "simulate: systolic frames");
DEFINE_int32(tags, 2000, "simulate: tracked tags");
DEFINE_double(noise, 0.5, "simulate: Gaussian noise per coordinate, mm");
DEFINE_double(outliers, 0.0, "simulate: fraction of outlier points");
DEFINE_int32(seed, 1, "simulate: random seed");

namespace pfdm {
namespace {

constexpr char kUsage[] =
    "pfdm <command> [flags]\n"
    "  fit       --points FILE --out DIR [--model paper|superellipsoid]\n"
    "  simulate  --out FILE.csv [--noise 0.5 --outliers 0 --frames 5]\n"
    "Run 'pfdm --help' for every flag.";

Eigen::Vector3d ParsePoint(const std::string& flag, const std::string& text) {
  Eigen::Vector3d point;
  std::istringstream in(text);
  char comma1 = 0, comma2 = 0;
  in >> point.x() >> comma1 >> point.y() >> comma2 >> point.z();
  if (!in || comma1 != ',' || comma2 != ',' || !(in >> std::ws).eof() ||
      !point.allFinite()) {
    throw InputError("--" + flag + " must be x,y,z in mm, got '" + text + "'");
  }
  return point;
}

PointSequence ReadPoints() {
  if (FLAGS_points.empty()) throw InputError("fit needs --points FILE");
  std::string format = FLAGS_format;
  if (format == "auto") {
    const std::filesystem::path path(FLAGS_points);
    format = std::filesystem::is_directory(path) ||
                     path.filename().string().rfind("GPFile", 0) == 0
                 ? "gpfile"
                 : "csv";
  }
  if (format == "csv") return ReadPointsCsv(FLAGS_points);
  if (format == "gpfile") {
    return ReadGpFiles(FLAGS_points, ExpandContourAlias(FLAGS_contours));
  }
  throw InputError("unknown --format '" + FLAGS_format +
                   "' (expected csv, gpfile or auto)");
}

int Fit() {
  if (FLAGS_out.empty()) throw InputError("fit needs --out DIR");
  const ModelConfig config = ModelConfig::FromName(FLAGS_model, FLAGS_knots);
  FitOptions options;
  options.smoothness_weight = FLAGS_smoothness;
  options.prior_weight = FLAGS_prior;
  options.loss = FLAGS_loss;
  options.loss_scale_mm = FLAGS_loss_scale;
  options.num_threads = FLAGS_threads;
  if (FLAGS_apex.empty() != FLAGS_base.empty()) {
    throw InputError("--apex and --base go together");
  }
  if (!FLAGS_apex.empty()) {
    options.hint = AxisHint{ParsePoint("apex", FLAGS_apex),
                            ParsePoint("base", FLAGS_base)};
  }
  const PointSequence points = ReadPoints();
  const SequenceFit fit = FitSequence(points, config, options);
  WriteFitOutputs(FLAGS_out, points, fit, options);
  for (const FrameFit& frame : fit.frames) {
    std::printf("frame %3d  points %5zu  rms %.3f mm  max %.3f mm  %s\n",
                frame.frame, frame.residuals.size(), frame.rms_mm,
                frame.max_distance_mm, frame.termination.c_str());
  }
  std::printf("wrote %s/fit.json, parameters.csv, frame_*.vtk\n",
              FLAGS_out.c_str());
  return 0;
}

int Simulate() {
  if (FLAGS_out.empty()) throw InputError("simulate needs --out FILE.csv");
  PhantomOptions options;
  options.num_frames = FLAGS_frames;
  options.num_points = FLAGS_tags;
  options.noise_mm = FLAGS_noise;
  options.outlier_fraction = FLAGS_outliers;
  options.seed = FLAGS_seed;
  if (options.num_frames < 1 || options.num_points < 1 || options.noise_mm < 0 ||
      options.outlier_fraction < 0 || options.outlier_fraction > 1) {
    throw InputError("simulate needs --frames >= 1, --tags >= 1, --noise >= 0 "
                     "and 0 <= --outliers <= 1");
  }
  const Phantom phantom = MakePhantom(options);
  std::filesystem::path truth(FLAGS_out);
  truth.replace_filename(truth.stem().string() + "_truth.csv");
  const std::string points_csv = ToPointsCsv(phantom.points);
  const std::string truth_csv = ParametersCsv(phantom.truth);
  if (truth.has_parent_path()) EnsureDirectory(truth.parent_path().string());
  WriteFileAtomically(FLAGS_out, points_csv);
  WriteFileAtomically(truth.string(), truth_csv);
  std::printf("wrote %s (%d frames x %d tags) and %s\n", FLAGS_out.c_str(),
              options.num_frames, options.num_points, truth.c_str());
  return 0;
}

}  // namespace
}  // namespace pfdm

int main(int argc, char** argv) {
  gflags::SetUsageMessage(pfdm::kUsage);
  gflags::ParseCommandLineFlags(&argc, &argv, true);
  if (argc != 2) {
    std::fprintf(stderr, "%s\n", pfdm::kUsage);
    return 2;
  }
  const std::string command = argv[1];
  try {
    if (command == "fit") return pfdm::Fit();
    if (command == "simulate") return pfdm::Simulate();
    std::fprintf(stderr, "pfdm: unknown command '%s'\n%s\n", command.c_str(),
                 pfdm::kUsage);
    return 2;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "pfdm: error: %s\n", error.what());
    return 1;
  }
}
