// pfdm batch: fits a cohort, one case per worker thread, resumable and
// shardable (a Slurm array runs the same command with --shard i/n).
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <thread>

#include "pfdm/batch/batch_manifest.h"
#include "pfdm/batch/batch_summary.h"
#include "pfdm/batch/case_folder.h"
#include "pfdm/cli/commands.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/io/fit_output.h"
#include "pfdm/io/landmark_axis.h"
#include "pfdm/io/mitral_valve_planes.h"
#include "pfdm/io/point_source.h"
#include "pfdm/io/rv_insertion_source.h"
#include "pfdm/report/fit_analysis.h"
#include "pfdm/report/gnuplot.h"
#include "pfdm/util/atomic_file.h"
#include "pfdm/util/error.h"
#include "pfdm/util/version.h"

DEFINE_string(manifest, "", "batch: CSV with columns case,points[,contours]");
DEFINE_int32(jobs, 1, "batch: cases fitted at once, one per thread, 1 to 256");
DEFINE_string(shard, "0/1",
              "batch: i/n, take every n-th case from the i-th "
              "(0-based), e.g. --shard $SLURM_ARRAY_TASK_ID/$N");
DECLARE_string(format);
DECLARE_string(contours);

namespace pfdm {
namespace {

namespace fs = std::filesystem;

// The case's error, kept beside its (absent) outputs for the summary of a
// later run, which retries the case; only in a folder of pfdm's own.
// Recording it may fail too (a full disk); that must not end the worker,
// and with it the batch.  Returns the message, with that failure if any.
std::string RecordFailure(const std::string& dir, std::string message) {
  try {
    ClaimCaseFolder(dir);
    WriteFileAtomically(dir + "/error.txt", message + "\n");
  } catch (const std::exception& also) {
    if (message != also.what()) {
      message += " (and " + std::string(also.what()) + ")";
    }
  }
  return message;
}

// Fits one case and writes its outputs; returns the progress line.
std::string RunCase(const BatchCase& c, const std::string& out,
                    const ModelConfig& config, const FitOptions& options) {
  const std::string dir = out + "/" + c.name;
  if (CaseStatus(dir, c.name).status == "done") {
    return "skipped, fit.json exists";
  }
  // A folder that is not pfdm's fails alone, untouched: its reason is
  // found again by the summary.
  const std::string refusal = CaseFolderRefusal(dir);
  if (!refusal.empty()) return "FAILED: " + refusal;
  const auto start = std::chrono::steady_clock::now();
  try {
    ClaimCaseFolder(dir);
    CheckFitOutputFolder(dir, c.points);
    const PointSequence points =
        ReadPoints(c.points, FLAGS_format,
                   c.contours.empty() ? FLAGS_contours : c.contours);
    CheckOptionsAgainstPoints(options, points);
    const std::vector<BasePlane> planes = BasePlanesFromFlags(c.points);
    FitOptions case_options = options;
    AddLandmarkAxis(c.points, &case_options);
    SvgRendering plots;  // gnuplot loads while the case is fitted.
    const SequenceFit fit = FitSequence(points, config, case_options);
    CheckPlanesBelowApex(c.points, planes, fit);
    // The case's own RV_INSERT points, if any, place its AHA segments.
    const RegionLayout layout =
        AnatomicalLayout(fit.ModelAt(0), RvInsertionFrom("", c.points));
    FitAnalysis analysis =
        AnalyzeFit(fit, planes, layout, ShowExtrapolatedFromFlags());
    analysis.made_by = CommandLine() + " (case " + c.name + ")";
    analysis.made_utc = UtcMinuteNow();
    WriteFitOutputs(dir, points, fit, analysis, options, VtkOutputFromFlags(),
                    &plots);
    fs::remove(dir + "/error.txt");
    RemoveAbandonedTemporaries(dir, "error.txt");
  } catch (const std::exception& error) {
    return "FAILED: " + RecordFailure(dir, error.what());
  }
  const CaseSummary s = CaseStatus(dir, c.name);
  char twist[32] = "n/a";  // An ES without tracked points (contours).
  if (s.twist_measured) {
    std::snprintf(twist, sizeof(twist), "%.1f deg", s.net_twist_deg);
  }
  // A mid-wall or epicardial volume's fraction is no ejection fraction;
  // summary.csv leaves it empty too.
  char ef[48] = "n/a";
  if (s.volume_surface == "cavity" && !std::isnan(s.ejection_fraction)) {
    std::snprintf(ef, sizeof(ef), "%.1f %%", 100.0 * s.ejection_fraction);
  } else if (s.volume_surface != "cavity") {
    std::snprintf(ef, sizeof(ef), "n/a (a %s surface)",
                  s.volume_surface.c_str());
  }
  char line[240];
  std::snprintf(
      line, sizeof(line),
      "done, %s, %d frames, max RMS %.2f mm, EF %s, net twist at ES %s, "
      "%.1f s",
      s.quality.c_str(), s.frames, s.max_rms_mm, ef, twist,
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count());
  return line;
}

}  // namespace

int RunBatch() {
  if (FLAGS_manifest.empty())
    throw InputError("batch needs --manifest FILE.csv");
  if (FLAGS_out.empty()) throw InputError("batch needs --out DIR");
  if (FLAGS_jobs < 1 || FLAGS_jobs > 256) {
    throw InputError("--jobs must be between 1 and 256, got " +
                     std::to_string(FLAGS_jobs));
  }
  const Shard shard = ParseShard(FLAGS_shard);
  const std::vector<BatchCase> all = ReadManifest(FLAGS_manifest);
  const std::vector<BatchCase> mine = CasesOfShard(all, shard);
  const ModelConfig config = ModelConfigFromFlags();
  const FitOptions options = FitOptionsFromFlags();
  BasePlanesFromFlags("");  // Checks --base_plane before any case.
  VtkOutputFromFlags();
  EnsureDirectory(FLAGS_out);

  std::atomic<size_t> next{0};
  std::atomic<int> finished{0}, failed{0};
  std::mutex print;
  auto worker = [&] {
    for (size_t i = next++; i < mine.size(); i = next++) {
      std::string result;
      try {
        result = RunCase(mine[i], FLAGS_out, config, options);
      } catch (const std::exception& error) {  // An escape would terminate.
        result = std::string("FAILED: ") + error.what();
      }
      const bool bad = result.rfind("FAILED", 0) == 0;
      std::lock_guard<std::mutex> lock(print);
      failed += bad;
      std::printf("[%d/%zu] %s: %s\n", ++finished, mine.size(),
                  mine[i].name.c_str(), result.c_str());
      std::fflush(stdout);
    }
  };
  std::vector<std::thread> threads;
  const int jobs = std::min<int>(FLAGS_jobs, std::max<size_t>(1, mine.size()));
  for (int j = 0; j < jobs; ++j) threads.emplace_back(worker);
  for (std::thread& thread : threads) thread.join();

  // The whole manifest, so the last shard to finish (or a final run with
  // everything done) leaves a complete table.
  std::vector<CaseSummary> summary;
  int done = 0, warned = 0, implausible = 0;
  for (const BatchCase& c : all) {
    summary.push_back(CaseStatus(FLAGS_out + "/" + c.name, c.name));
    done += summary.back().status == "done";
    warned += summary.back().quality == "warning";
    implausible += summary.back().quality == "failed";
  }
  WriteFileAtomically(FLAGS_out + "/summary.csv", SummaryCsv(summary));
  std::printf(
      "wrote %s/summary.csv: %d of %zu cases done (%d with warnings, %d "
      "implausible)\n",
      FLAGS_out.c_str(), done, all.size(), warned, implausible);
  if (failed > 0) {
    throw InputError(std::to_string(failed.load()) + " of " +
                     std::to_string(mine.size()) + " cases failed, see " +
                     FLAGS_out + "/summary.csv");
  }
  if (implausible > 0) {
    std::fprintf(stderr,
                 "pfdm: %d of %zu cases implausible (summary.csv's quality "
                 "and quality_reasons say why)\n",
                 implausible, all.size());
    return kExitImplausible;
  }
  return 0;
}

}  // namespace pfdm
