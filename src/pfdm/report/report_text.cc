#include "pfdm/report/report_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "pfdm/report/fit_analysis.h"

namespace pfdm {

// "n/a" for a number the data cannot determine (kNotMeasured).
std::string Fixed(double value, int digits) {
  if (!Measured(value)) return "n/a";
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", digits, value);
  // "-0.0" from a value that rounds to zero reads as a sign that is not
  // there (frame 0's strains, say).
  const std::string out = text;
  if (out[0] == '-' && out.find_first_not_of("-0.") == std::string::npos) {
    return out.substr(1);
  }
  return out;
}

// A background tint for a value in [-scale, scale]: orange for positive,
// blue for negative, white at zero, so a table reads like a map.
std::string Tint(double value, double scale) {
  if (!Measured(value)) return "";
  const double x = std::clamp(value / scale, -1.0, 1.0);
  const int fade = static_cast<int>(std::lround(255 - 110 * std::abs(x)));
  char style[64];
  if (x >= 0) {
    std::snprintf(style, sizeof(style), " style=\"background:#ff%02x%02x\"",
                  std::min(255, fade + 40), fade);
  } else {
    std::snprintf(style, sizeof(style), " style=\"background:#%02x%02xff\"",
                  fade, std::min(255, fade + 40));
  }
  return style;
}

// A value and its unit ("&deg;", " %"), or "n/a" alone.
std::string WithUnit(double value, int digits, const char* unit) {
  return Measured(value) ? Fixed(value, digits) + unit : "n/a";
}

// What the volumes are of, as the page names them.
std::string VolumeName(const FitAnalysis& analysis) {
  return analysis.volume_surface == "cavity" ? "cavity volume"
         : analysis.volume_surface == "epicardial"
             ? "volume inside the epicardium"
             : "mid-wall enclosed volume";
}

}  // namespace pfdm
