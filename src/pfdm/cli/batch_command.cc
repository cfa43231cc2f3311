// pfdm batch: fits a cohort, one case per worker thread, resumable and
// shardable (a Slurm array runs the same command with --shard i/n).
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <thread>

#include "pfdm/batch/batch_manifest.h"
#include "pfdm/batch/batch_summary.h"
#include "pfdm/cli/commands.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/io/fit_output.h"
#include "pfdm/io/landmark_axis.h"
#include "pfdm/io/point_source.h"
#include "pfdm/report/fit_analysis.h"
#include "pfdm/report/gnuplot.h"
#include "pfdm/util/atomic_file.h"
#include "pfdm/util/error.h"

DEFINE_string(manifest, "", "batch: CSV with columns case,points[,contours]");
DEFINE_int32(jobs, 1, "batch: cases fitted at once, one per thread");
DEFINE_string(shard, "0/1",
              "batch: i/n, take every n-th case from the i-th "
              "(0-based), e.g. --shard $SLURM_ARRAY_TASK_ID/$N");
DECLARE_string(format);
DECLARE_string(contours);

namespace pfdm {
namespace {

namespace fs = std::filesystem;

std::string ReadWhole(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// A case is done when its fit.json exists (written last), failed when its
// error.txt does, pending otherwise.
CaseSummary StatusOf(const BatchCase& c, const std::string& out) {
  const std::string dir = out + "/" + c.name;
  CaseSummary summary;
  summary.name = c.name;
  if (fs::exists(dir + "/fit.json")) {
    try {
      return SummaryFromFitJson(c.name, ReadWhole(dir + "/fit.json"),
                                dir + "/fit.json");
    } catch (const InputError& error) {
      // One unreadable case must not cost the cohort its summary; it is
      // fitted again by the next run.
      summary.status = "failed";
      summary.error = error.what();
      return summary;
    }
  }
  summary.status = "pending";
  if (fs::exists(dir + "/error.txt")) {
    summary.status = "failed";
    summary.error = ReadWhole(dir + "/error.txt");
    while (!summary.error.empty() && summary.error.back() == '\n') {
      summary.error.pop_back();
    }
  }
  return summary;
}

// Fits one case and writes its outputs; returns the progress line.
std::string RunCase(const BatchCase& c, const std::string& out,
                    const ModelConfig& config, const FitOptions& options) {
  const std::string dir = out + "/" + c.name;
  if (StatusOf(c, out).status == "done") return "skipped, fit.json exists";
  const auto start = std::chrono::steady_clock::now();
  try {
    CheckFitOutputFolder(dir, c.points);
    const PointSequence points =
        ReadPoints(c.points, FLAGS_format,
                   c.contours.empty() ? FLAGS_contours : c.contours);
    FitOptions case_options = options;
    AddLandmarkAxis(c.points, &case_options);
    SvgRendering plots;  // gnuplot loads while the case is fitted.
    const SequenceFit fit = FitSequence(points, config, case_options);
    WriteFitOutputs(dir, points, fit,
                    AnalyzeFit(fit, BasePlanesFromFlags(c.points)), options,
                    VtkFormatFromFlags(), &plots);
    fs::remove(dir + "/error.txt");
  } catch (const std::exception& error) {
    // The case's error stays beside its (absent) outputs for the summary of
    // a later run, which retries the case.
    // Recording it may fail too (DIR/<case> a plain file, a full disk);
    // that must not end the worker, and with it the batch.
    std::string message = error.what();
    try {
      EnsureDirectory(dir);
      WriteFileAtomically(dir + "/error.txt", message + "\n");
    } catch (const std::exception& also) {
      if (message != also.what()) {
        message += " (and " + std::string(also.what()) + ")";
      }
    }
    return "FAILED: " + message;
  }
  const CaseSummary s = StatusOf(c, out);
  char line[200];
  std::snprintf(
      line, sizeof(line),
      "done, %d frames, max RMS %.2f mm, EF %.1f %%, net twist at "
      "ES %.1f deg, %.1f s",
      s.frames, s.max_rms_mm, 100.0 * s.ejection_fraction, s.net_twist_deg,
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count());
  return line;
}

}  // namespace

int RunBatch() {
  if (FLAGS_manifest.empty())
    throw InputError("batch needs --manifest FILE.csv");
  if (FLAGS_out.empty()) throw InputError("batch needs --out DIR");
  if (FLAGS_jobs < 1) throw InputError("--jobs must be at least 1");
  const Shard shard = ParseShard(FLAGS_shard);
  const std::vector<BatchCase> all = ReadManifest(FLAGS_manifest);
  const std::vector<BatchCase> mine = CasesOfShard(all, shard);
  const ModelConfig config = ModelConfigFromFlags();
  const FitOptions options = FitOptionsFromFlags();
  BasePlanesFromFlags("");  // Checks --base_plane before any case.
  VtkFormatFromFlags();
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
  int done = 0;
  for (const BatchCase& c : all) {
    summary.push_back(StatusOf(c, FLAGS_out));
    done += summary.back().status == "done";
  }
  WriteFileAtomically(FLAGS_out + "/summary.csv", SummaryCsv(summary));
  std::printf("wrote %s/summary.csv: %d of %zu cases done\n", FLAGS_out.c_str(),
              done, all.size());
  if (failed > 0) {
    throw InputError(std::to_string(failed.load()) + " of " +
                     std::to_string(mine.size()) + " cases failed, see " +
                     FLAGS_out + "/summary.csv");
  }
  return 0;
}

}  // namespace pfdm
