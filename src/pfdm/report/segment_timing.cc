#include "pfdm/report/segment_timing.h"

#include <cmath>

namespace pfdm {
namespace {

// Region r's most negative Ecc and its frame; not measured where a frame
// has no value.
SegmentPeak PeakOfRegion(const std::vector<std::vector<RegionMotion>>& motion,
                         size_t r) {
  SegmentPeak peak;
  for (size_t t = 0; t < motion.size(); ++t) {
    const double ecc =
        r < motion[t].size() ? motion[t][r].ecc_percent : kNotMeasured;
    if (!Measured(ecc)) return SegmentPeak();
    if (peak.frame < 0 || ecc < peak.percent) {
      peak.percent = ecc;
      peak.frame = static_cast<int>(t);
    }
  }
  return peak;
}

double SampleSd(const std::vector<double>& values) {
  if (values.size() < 2) return kNotMeasured;
  double mean = 0.0;
  for (double v : values) mean += v;
  mean /= values.size();
  double squares = 0.0;
  for (double v : values) squares += (v - mean) * (v - mean);
  return std::sqrt(squares / (values.size() - 1));
}

}  // namespace

Dyssynchrony MeasureDyssynchrony(
    const std::vector<WallRegion>& regions,
    const std::vector<std::vector<RegionMotion>>& motion,
    const std::vector<double>& time_ms, int ed_frame) {
  Dyssynchrony result;
  result.in_ms = !motion.empty() && time_ms.size() == motion.size();
  std::vector<double> counted;
  for (size_t r = 0; r < regions.size(); ++r) {
    SegmentPeak peak = PeakOfRegion(motion, r);
    if (peak.frame >= 0) {
      peak.time_to_peak = result.in_ms
                              ? time_ms[peak.frame] - time_ms.at(ed_frame)
                              : static_cast<double>(peak.frame - ed_frame);
      if (regions[r].level != kApex) counted.push_back(peak.time_to_peak);
    }
    result.peaks.push_back(peak);
  }
  result.segments = static_cast<int>(counted.size());
  result.index = SampleSd(counted);
  return result;
}

}  // namespace pfdm
