// When each segment's circumferential strain peaks, and how far the
// segments' peaks spread: the dyssynchrony index.
#ifndef PFDM_REPORT_SEGMENT_TIMING_H_
#define PFDM_REPORT_SEGMENT_TIMING_H_

#include <vector>

#include "pfdm/report/clinical_summary.h"
#include "pfdm/report/wall_motion.h"

namespace pfdm {

struct SegmentPeak {
  double percent = kNotMeasured;  // The most negative Ecc over the frames.
  int frame = -1;                 // Its frame; -1 where not measured.
  // From ED to the peak: ms where the frames' times are known, else frames.
  double time_to_peak = kNotMeasured;
};

struct Dyssynchrony {
  std::vector<SegmentPeak> peaks;  // One per region.
  // The standard deviation (n - 1 in the denominator) of time_to_peak over
  // the segments counted: those of the 16 about the axis (not the apex
  // cap, whose circumferential direction turns about its pole) with Ecc
  // measured in every frame.  kNotMeasured with fewer than 2.
  double index = kNotMeasured;
  int segments = 0;    // Counted.
  bool in_ms = false;  // Times in ms, else in frames.
};

// motion: [frame][region] (FitAnalysis::region_motion); time_ms: per frame,
// or empty (then times are frame counts); ed_frame: where time starts.
Dyssynchrony MeasureDyssynchrony(
    const std::vector<WallRegion>& regions,
    const std::vector<std::vector<RegionMotion>>& motion,
    const std::vector<double>& time_ms, int ed_frame);

}  // namespace pfdm

#endif  // PFDM_REPORT_SEGMENT_TIMING_H_
