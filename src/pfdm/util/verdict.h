// A fit's honest verdict on one frame: ok, warning or failed, with the
// reasons (the solver's termination says only what the solver did).  The
// fit adds what it sees of its own solve (fit/stages/frame_verdict.h), the
// analysis what it sees of the clinical numbers (report/plausibility.h).
#ifndef PFDM_UTIL_VERDICT_H_
#define PFDM_UTIL_VERDICT_H_

#include <string>
#include <vector>

namespace pfdm {

// Ordered: a frame's quality is its worst reason's.
enum class Quality { kOk = 0, kWarning = 1, kFailed = 2 };

// "ok", "warning", "failed".
const char* QualityName(Quality quality);

struct VerdictReason {
  Quality severity = Quality::kWarning;
  // Stable, for programs: "unsettled", "rms_high", "regularizer_share", ...
  std::string code;
  // For people: what was measured against what.
  std::string text;
};

class Verdict {
 public:
  void Warn(const std::string& code, const std::string& text) {
    reasons_.push_back({Quality::kWarning, code, text});
  }
  void Fail(const std::string& code, const std::string& text) {
    reasons_.push_back({Quality::kFailed, code, text});
  }
  void Add(const Verdict& other);

  Quality quality() const;
  const std::vector<VerdictReason>& reasons() const { return reasons_; }
  bool Has(const std::string& code) const;
  // "ok", or the quality and the reasons: "warning: RMS 5.5 mm, 5.0 times
  // the sequence's median 1.1 mm; closest points still moving (22.6 mm)".
  std::string Summary() const;

 private:
  std::vector<VerdictReason> reasons_;
};

// The worst of the verdicts' qualities (kOk for none).
Quality WorstQuality(const std::vector<Verdict>& verdicts);

}  // namespace pfdm

#endif  // PFDM_UTIL_VERDICT_H_
