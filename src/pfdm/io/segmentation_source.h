// pfdm fit --segmentation: a label map's LV contours and RV insertion, as
// the fit and the report take guide points'.
#ifndef PFDM_IO_SEGMENTATION_SOURCE_H_
#define PFDM_IO_SEGMENTATION_SOURCE_H_

#include <optional>
#include <string>

#include "pfdm/report/fit_analysis.h"
#include "pfdm/report/rv_insertion.h"
#include "pfdm/segmentation/mask_contours.h"

namespace pfdm {

struct Segmentation {
  LabelVolume volume;
  LabelMap labels;
  MaskContours contours;
  // From the contours' RV contact (nullopt where the RV never touches the
  // myocardium, or without an RV label).
  std::optional<RvInsertion> rv_insertion;
};

// ReadLabelVolume(path), ParseLabelMap(labels), ExtractMaskContours.
// Throws InputError.
Segmentation ReadSegmentation(const std::string& path,
                              const std::string& labels);

// What the analysis of a fit of s's contours keeps of s: its record
// (fit.json's "segmentation") and its misaligned slices as warnings in
// the frames' verdicts.
void AttachSegmentation(const Segmentation& s, FitAnalysis* analysis);

}  // namespace pfdm

#endif  // PFDM_IO_SEGMENTATION_SOURCE_H_
