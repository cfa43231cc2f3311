// The report's numbers as text: fixed decimals with "n/a" for what the
// data cannot determine, units, a table cell's tint, and what the volumes
// are of.
#ifndef PFDM_REPORT_REPORT_TEXT_H_
#define PFDM_REPORT_REPORT_TEXT_H_

#include <string>

namespace pfdm {

struct FitAnalysis;

// `digits` decimals; "n/a" for kNotMeasured, and never "-0.0".
std::string Fixed(double value, int digits);

// A background tint style for a value in [-scale, scale]: orange for
// positive, blue for negative, white at zero; "" for kNotMeasured.
std::string Tint(double value, double scale);

// A value and its unit ("&deg;", " %"), or "n/a" alone.
std::string WithUnit(double value, int digits, const char* unit);

// "cavity volume", "volume inside the epicardium" or "mid-wall enclosed
// volume".
std::string VolumeName(const FitAnalysis& analysis);

}  // namespace pfdm

#endif  // PFDM_REPORT_REPORT_TEXT_H_
