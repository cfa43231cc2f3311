// pfdm simulate: the synthetic SPAMM-like LV phantom and its ground truth.
#include <cstdio>
#include <filesystem>

#include "pfdm/cli/commands.h"
#include "pfdm/io/fit_output.h"
#include "pfdm/io/point_writer.h"
#include "pfdm/phantom/phantom.h"
#include "pfdm/util/atomic_file.h"
#include "pfdm/util/error.h"

DEFINE_int32(frames, 5, "simulate: systolic frames");
DEFINE_int32(tags, 2000, "simulate: tracked tags");
DEFINE_double(noise, 0.5, "simulate: Gaussian noise per coordinate, mm");
DEFINE_double(outliers, 0.0, "simulate: fraction of outlier points");
DEFINE_int32(seed, 1, "simulate: random seed");

namespace pfdm {

int RunSimulate() {
  if (FLAGS_out.empty()) throw InputError("simulate needs --out FILE.csv");
  PhantomOptions options;
  options.num_frames = FLAGS_frames;
  options.num_points = FLAGS_tags;
  options.noise_mm = FLAGS_noise;
  options.outlier_fraction = FLAGS_outliers;
  options.seed = FLAGS_seed;
  // Written so that NaN fails every test (it once wrote NaN rows).
  if (!(options.num_frames >= 1 && options.num_frames <= 1000 &&
        options.num_points >= 1 && options.num_points <= 1000000 &&
        options.noise_mm >= 0 && options.noise_mm <= 1000 &&
        options.outlier_fraction >= 0 && options.outlier_fraction <= 1)) {
    throw InputError(
        "simulate needs 1 <= --frames <= 1000, 1 <= --tags <= 1e6, "
        "0 <= --noise <= 1000 (mm) and 0 <= --outliers <= 1");
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

}  // namespace pfdm
