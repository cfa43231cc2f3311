#include "pfdm/util/verdict.h"

#include <algorithm>

namespace pfdm {

const char* QualityName(Quality quality) {
  switch (quality) {
    case Quality::kOk:
      return "ok";
    case Quality::kWarning:
      return "warning";
    case Quality::kFailed:
      return "failed";
  }
  return "ok";
}

void Verdict::Add(const Verdict& other) {
  reasons_.insert(reasons_.end(), other.reasons_.begin(), other.reasons_.end());
}

Quality Verdict::quality() const {
  Quality worst = Quality::kOk;
  for (const VerdictReason& reason : reasons_) {
    worst = std::max(worst, reason.severity);
  }
  return worst;
}

bool Verdict::Has(const std::string& code) const {
  return std::any_of(
      reasons_.begin(), reasons_.end(),
      [&](const VerdictReason& reason) { return reason.code == code; });
}

std::string Verdict::Summary() const {
  std::string summary = QualityName(quality());
  for (size_t i = 0; i < reasons_.size(); ++i) {
    summary += (i == 0 ? ": " : "; ") + reasons_[i].text;
  }
  return summary;
}

Quality WorstQuality(const std::vector<Verdict>& verdicts) {
  Quality worst = Quality::kOk;
  for (const Verdict& verdict : verdicts) {
    worst = std::max(worst, verdict.quality());
  }
  return worst;
}

}  // namespace pfdm
