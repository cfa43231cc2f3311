#include "pfdm/report/verdict_box.h"

#include <sstream>

#include "pfdm/util/markup_escape.h"
#include "pfdm/util/verdict.h"

namespace pfdm {
namespace {

struct Look {
  const char* background;
  const char* border;
  const char* headline;
};

Look LookOf(Quality quality) {
  switch (quality) {
    case Quality::kOk:
      return {"#eaf6ea", "#5a9a5a",
              "Quality: ok. Every frame passed the fit's checks."};
    case Quality::kWarning:
      return {"#fff5e0", "#c98a12",
              "Quality: warning. Some numbers may be off: read the reasons."};
    case Quality::kFailed:
      return {"#fde8e8", "#c0392b",
              "Quality: failed. The fit is implausible: do not use these "
              "numbers."};
  }
  return LookOf(Quality::kOk);
}

}  // namespace

std::string VerdictBoxHtml(const SequenceFit& fit,
                           const FitAnalysis& analysis) {
  const Look look = LookOf(WorstQuality(analysis.verdicts));
  std::ostringstream h;
  h << "<div class=\"verdict\" style=\"background:" << look.background
    << ";border:2px solid " << look.border
    << ";border-radius:6px;padding:8px 14px;margin:14px 0\"><b>"
    << look.headline << "</b>";
  std::ostringstream list;
  for (size_t t = 0; t < analysis.verdicts.size(); ++t) {
    const Verdict& verdict = analysis.verdicts[t];
    if (verdict.quality() == Quality::kOk) continue;
    list << "<li>frame " << fit.frames[t].frame << ": "
         << EscapeMarkup(verdict.Summary()) << "</li>";
  }
  if (!list.str().empty()) h << "<ul>" << list.str() << "</ul>";
  h << "<span style=\"font-size:12px;color:#555\">Each reason measures one "
       "thing against a stated bound (fit.json's quality, "
       "docs/verdict.md).</span></div>\n";
  return h.str();
}

}  // namespace pfdm
