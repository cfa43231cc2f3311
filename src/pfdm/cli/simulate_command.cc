// pfdm simulate: a synthetic LV with tracked tags and its ground truth;
// --phantom model (the model's own equations) or lv (the analytic LV).
#include <cstdio>
#include <filesystem>

#include "pfdm/cli/commands.h"
#include "pfdm/io/fit_output.h"
#include "pfdm/io/point_writer.h"
#include "pfdm/phantom/lv_phantom.h"
#include "pfdm/phantom/lv_phantom_names.h"
#include "pfdm/phantom/lv_truth_json.h"
#include "pfdm/phantom/phantom.h"
#include "pfdm/util/atomic_file.h"
#include "pfdm/util/error.h"

DEFINE_int32(frames, 5,
             "simulate: frames (--phantom lv: 5, or 9 for --kinematics cycle)");
DEFINE_int32(tags, 2000, "simulate: tracked tags");
DEFINE_double(noise, 0.5, "simulate: Gaussian noise per coordinate, mm");
DEFINE_double(outliers, 0.0,
              "simulate: fraction of outlier points (--phantom model: moved "
              "10 mm, lv: 5 to 10 mm, in a random direction)");
DEFINE_int32(seed, 1, "simulate: random seed");
DEFINE_string(phantom, "model",
              "simulate: model (the model's own equations) or lv (the "
              "analytic LV, independent of the model)");
DEFINE_string(kinematics, "systole",
              "simulate --phantom lv: systole, cycle, rigid-axial, "
              "rigid-lateral, rigid-tilt, rigid-spin or static");
DEFINE_string(wall_tags, "midwall",
              "simulate --phantom lv: tags (or contours) on the midwall, "
              "through the wall (both walls), on the endo(cardium) or on "
              "the epi(cardium)");
DEFINE_bool(breathing, true,
            "simulate --phantom lv: rigid breathing motion in systole and "
            "cycle (--nobreathing: none)");
DEFINE_bool(lesion, false,
            "simulate --phantom lv: mid segment 2 contracts 70 % less");
DEFINE_string(region, "full",
              "simulate --phantom lv: full, or midventricular (ED heights "
              "30-72 % of the length: no apex, 40 mm long)");
DEFINE_string(sampling, "tags",
              "simulate --phantom lv: tags (tracked), or sax-slices "
              "(untracked contours on --slices fixed short-axis planes; "
              "--tags points a frame)");
DEFINE_string(geometry, "prolate",
              "simulate --phantom lv: prolate (the whole LV) or cylinder (a "
              "mid-ventricular segment, wall 10 mm, no apex; analytic truth)");
DEFINE_string(thickening, "designed",
              "simulate --phantom lv: designed (contraction quadratic across "
              "the wall) or incompressible (the endocardium moving farthest)");
DEFINE_int32(slices, 0,
             "simulate --phantom lv --sampling sax-slices: planes (0: 3 "
             "midventricular, 9 full)");

namespace pfdm {
namespace {

bool IsDefault(const char* flag) {
  return gflags::GetCommandLineFlagInfoOrDie(flag).is_default;
}

// Both phantoms' counts and noise, named with their values as the Python
// module's simulate names them.
void CheckSimulateFlags() {
  PhantomOptions options;
  options.num_frames = FLAGS_frames;
  options.num_points = FLAGS_tags;
  options.noise_mm = FLAGS_noise;
  options.outlier_fraction = FLAGS_outliers;
  CheckPhantomOptions(options);
}

// NAME.csv -> NAME_truth.<extension>
std::filesystem::path TruthPath(const char* extension) {
  std::filesystem::path truth(FLAGS_out);
  truth.replace_filename(truth.stem().string() + "_truth." + extension);
  return truth;
}

int RunModelPhantom() {
  PhantomOptions options;
  options.num_frames = FLAGS_frames;
  options.num_points = FLAGS_tags;
  options.noise_mm = FLAGS_noise;
  options.outlier_fraction = FLAGS_outliers;
  options.seed = FLAGS_seed;
  const Phantom phantom = MakePhantom(options);
  const std::filesystem::path truth = TruthPath("csv");
  const std::string points_csv = ToPointsCsv(phantom.points);
  const std::string truth_csv = ParametersCsv(phantom.truth);
  if (truth.has_parent_path()) EnsureDirectory(truth.parent_path().string());
  WriteFileAtomically(FLAGS_out, points_csv);
  WriteFileAtomically(truth.string(), truth_csv);
  std::printf("wrote %s (%d frames x %d tags) and %s\n", FLAGS_out.c_str(),
              options.num_frames, options.num_points, truth.c_str());
  return 0;
}

int RunLvPhantom() {
  LvPhantomOptions options;
  LvPhantomNames names;
  names.kinematics = FLAGS_kinematics;
  names.wall_tags = FLAGS_wall_tags;
  names.region = FLAGS_region;
  names.sampling = FLAGS_sampling;
  names.geometry = FLAGS_geometry;
  names.thickening = FLAGS_thickening;
  SetLvPhantomNames(names, "--", &options);
  if (!(FLAGS_slices >= 0 && FLAGS_slices <= 1000)) {
    throw InputError("simulate needs 0 <= --slices <= 1000");
  }
  options.num_slices = FLAGS_slices;
  options.num_frames = IsDefault("frames") ? 0 : FLAGS_frames;
  options.num_tags = FLAGS_tags;
  options.noise_mm = FLAGS_noise;
  options.outlier_fraction = FLAGS_outliers;
  options.seed = FLAGS_seed;
  if (options.geometry == LvGeometry::kCylinder) {
    options.deformation = CylinderDeformation();
  }
  options.deformation.lesion = FLAGS_lesion;
  options.breathing = FLAGS_breathing;
  const LvPhantom phantom = MakeLvPhantom(options);
  const std::filesystem::path truth = TruthPath("json");
  const std::string points_csv = ToPointsCsv(phantom.points);
  const std::string truth_json = LvTruthJson(phantom);
  if (truth.has_parent_path()) EnsureDirectory(truth.parent_path().string());
  WriteFileAtomically(FLAGS_out, points_csv);
  WriteFileAtomically(truth.string(), truth_json);
  const std::string partial = IsDefault("region") && IsDefault("sampling")
                                  ? ""
                                  : " " + FLAGS_region + " " + FLAGS_sampling;
  std::printf("wrote %s (lv %s%s, %d frames x %d %s) and %s\n",
              FLAGS_out.c_str(), FLAGS_kinematics.c_str(), partial.c_str(),
              phantom.options.num_frames, options.num_tags,
              options.sampling == LvSampling::kTags ? "tags" : "points",
              truth.c_str());
  return 0;
}

}  // namespace

int RunSimulate() {
  if (FLAGS_out.empty()) throw InputError("simulate needs --out FILE.csv");
  CheckSimulateFlags();
  if (FLAGS_phantom == "lv") return RunLvPhantom();
  if (FLAGS_phantom != "model") {
    throw InputError("unknown --phantom '" + FLAGS_phantom + "' (model, lv)");
  }
  if (!IsDefault("kinematics") || !IsDefault("wall_tags") ||
      !IsDefault("lesion") || !IsDefault("breathing") || !IsDefault("region") ||
      !IsDefault("sampling") || !IsDefault("slices") ||
      !IsDefault("geometry") || !IsDefault("thickening")) {
    throw InputError(
        "--kinematics, --wall_tags, --lesion, --breathing, --region, "
        "--sampling, --slices, --geometry and --thickening need --phantom lv");
  }
  return RunModelPhantom();
}

}  // namespace pfdm
