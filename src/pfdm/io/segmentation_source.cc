#include "pfdm/io/segmentation_source.h"

#include "pfdm/io/label_map.h"
#include "pfdm/io/nifti_reader.h"

namespace pfdm {

Segmentation ReadSegmentation(const std::string& path,
                              const std::string& labels) {
  Segmentation s;
  s.labels = ParseLabelMap(labels);  // The flag before the file.
  s.volume = ReadLabelVolume(path);
  s.contours = ExtractMaskContours(s.volume, s.labels);
  if (!s.contours.rv_insertion.empty()) {
    RvInsertion insertion;
    insertion.unlabelled = s.contours.rv_insertion;
    insertion.source = "the RV's contact with the myocardium (" +
                       std::to_string(insertion.unlabelled.size() / 2) +
                       " slices of frame 0)";
    s.rv_insertion = insertion;
  }
  return s;
}

void AttachSegmentation(const Segmentation& s, FitAnalysis* analysis) {
  analysis->segmentation = RecordSegmentation(s.volume, s.labels, s.contours);
  const std::vector<Verdict> alignment = SliceAlignmentVerdicts(
      s.contours.misaligned, static_cast<int>(analysis->verdicts.size()));
  for (size_t t = 0; t < alignment.size(); ++t) {
    analysis->verdicts[t].Add(alignment[t]);
  }
}

}  // namespace pfdm
