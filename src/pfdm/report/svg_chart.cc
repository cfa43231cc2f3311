#include "pfdm/report/svg_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "pfdm/report/report_text.h"
#include "pfdm/util/markup_escape.h"

namespace pfdm {
namespace {

constexpr double kLeft = 52, kRight = 12, kTop = 34, kBottom = 40;
constexpr double kLegendRow = 16;

// Digits that tell ticks `step` apart.
int DigitsFor(double step) {
  return std::max(0, static_cast<int>(std::ceil(-std::log10(step) - 1e-9)));
}

struct PlotArea {
  double x0, x1, y0, y1;            // Data ranges.
  double left, right, top, bottom;  // Pixels.
  double X(double x) const {
    return left + (x - x0) / (x1 - x0) * (right - left);
  }
  double Y(double y) const {
    return bottom - (y - y0) / (y1 - y0) * (bottom - top);
  }
};

void Range(const std::vector<double>& values, double* low, double* high) {
  for (double v : values) {
    if (std::isnan(v)) continue;
    *low = std::min(*low, v);
    *high = std::max(*high, v);
  }
}

// Where value i's error bar is centred: on the value minus its bias.
double BarCentre(const ChartSeries& s, size_t i) {
  const double bias = i < s.bias.size() ? s.bias[i] : NAN;
  return std::isfinite(bias) ? s.y[i] - bias : s.y[i];
}

// The hover's interval: "+- w" about the value, or, when the bias moved
// its centre, the interval's ends.
std::string BarText(double y, double centre, double w) {
  if (centre == y) return " &#177; " + Fixed(w, 2) + " (95 %)";
  return ", 95 %: " + Fixed(centre - w, 2) + " to " + Fixed(centre + w, 2) +
         " (less the noise's bias)";
}

PlotArea PlotFrame(const Chart& chart, int legend_rows) {
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  Range(chart.x, &x0, &x1);
  for (const ChartSeries& s : chart.series) {
    Range(s.y, &y0, &y1);
    for (size_t i = 0; i < s.y.size() && i < s.half_width.size(); ++i) {
      if (!std::isfinite(s.half_width[i])) continue;
      const double centre = BarCentre(s, i);
      Range({centre - s.half_width[i], centre + s.half_width[i]}, &y0, &y1);
    }
  }
  if (chart.zero_line) Range({0.0}, &y0, &y1);
  if (!(x0 < x1)) x0 -= 1, x1 += 1;
  if (!(y0 < y1)) y0 -= 1, y1 += 1;
  const double pad = 0.06 * (y1 - y0);
  return {x0,       x1,
          y0 - pad, y1 + pad,
          kLeft,    chart.width - kRight,
          kTop,     chart.height - kBottom - legend_rows * kLegendRow};
}

void Axes(const Chart& chart, const PlotArea& f, std::ostringstream* out) {
  for (bool vertical : {true, false}) {
    const std::vector<double> ticks =
        vertical ? RoundTicks(f.x0, f.x1, 6) : RoundTicks(f.y0, f.y1, 5);
    const int digits = ticks.size() > 1 ? DigitsFor(ticks[1] - ticks[0]) : 0;
    for (double t : ticks) {
      if (vertical) {
        *out << "<line x1='" << f.X(t) << "' x2='" << f.X(t) << "' y1='"
             << f.top << "' y2='" << f.bottom << "' stroke='#e4e4e4'/>"
             << "<text x='" << f.X(t) << "' y='" << f.bottom + 14
             << "' text-anchor='middle'>" << Fixed(t, digits) << "</text>";
      } else {
        *out << "<line x1='" << f.left << "' x2='" << f.right << "' y1='"
             << f.Y(t) << "' y2='" << f.Y(t) << "' stroke='#e4e4e4'/>"
             << "<text x='" << f.left - 4 << "' y='" << f.Y(t) + 4
             << "' text-anchor='end'>" << Fixed(t, digits) << "</text>";
      }
    }
  }
  *out << "<rect x='" << f.left << "' y='" << f.top << "' width='"
       << f.right - f.left << "' height='" << f.bottom - f.top
       << "' fill='none' stroke='#888'/>"
       << "<text x='" << (f.left + f.right) / 2 << "' y='" << f.bottom + 30
       << "' text-anchor='middle'>" << EscapeMarkup(chart.x_label)
       << "</text><text transform='translate(13," << (f.top + f.bottom) / 2
       << ") rotate(-90)' text-anchor='middle'>" << EscapeMarkup(chart.y_label)
       << "</text>"
       << "<text x='" << chart.width / 2 << "' y='15' text-anchor='middle' "
       << "font-size='13' font-weight='bold'>" << EscapeMarkup(chart.title)
       << "</text>";
  if (chart.zero_line && f.y0 < 0 && f.y1 > 0) {
    *out << "<line x1='" << f.left << "' x2='" << f.right << "' y1='" << f.Y(0)
         << "' y2='" << f.Y(0) << "' stroke='#888' stroke-dasharray='4 3'/>";
  }
}

// ED and ES: dashed lines, labelled in the band above the plot, ES moved
// right of its line when the two would touch.
void Markers(const Chart& chart, const PlotArea& f, std::ostringstream* out) {
  const int marks[] = {chart.ed, chart.es};
  const char* names[] = {"ED", "ES"};
  for (int k = 0; k < 2; ++k) {
    const int i = marks[k];
    if (i < 0 || i >= static_cast<int>(chart.x.size())) continue;
    const double x = f.X(chart.x[i]);
    const bool crowded =
        k == 1 && chart.ed >= 0 && std::abs(x - f.X(chart.x[chart.ed])) < 22;
    *out << "<line x1='" << x << "' x2='" << x << "' y1='" << f.top << "' y2='"
         << f.bottom << "' stroke='#555' stroke-dasharray='2 3'/>"
         << "<text x='" << x + (crowded ? 14 : 0) << "' y='" << f.top - 4
         << "' text-anchor='middle' font-weight='bold'>" << names[k]
         << "</text>";
  }
}

void Curve(const Chart& chart, const ChartSeries& s, const PlotArea& f,
           std::ostringstream* out) {
  *out << "<g><title>" << EscapeMarkup(s.name) << "</title>";
  std::ostringstream path;
  bool pen_up = true;
  for (size_t i = 0; i < s.y.size() && i < chart.x.size(); ++i) {
    if (std::isnan(s.y[i])) {
      pen_up = true;
      continue;
    }
    path << (pen_up ? 'M' : 'L') << f.X(chart.x[i]) << ',' << f.Y(s.y[i]);
    pen_up = false;
  }
  *out << "<path d='" << path.str() << "' fill='none' stroke='" << s.color
       << "' stroke-width='" << s.width << "'/>";
  for (size_t i = 0; i < s.y.size() && i < chart.x.size(); ++i) {
    if (std::isnan(s.y[i])) continue;
    const double w = i < s.half_width.size() ? s.half_width[i] : 0.0;
    const bool bar = std::isfinite(w) && w > 0;
    const double centre = BarCentre(s, i);
    if (bar) {
      *out << "<line x1='" << f.X(chart.x[i]) << "' x2='" << f.X(chart.x[i])
           << "' y1='" << f.Y(centre - w) << "' y2='" << f.Y(centre + w)
           << "' stroke='" << s.color << "'/>";
    }
    *out << "<circle cx='" << f.X(chart.x[i]) << "' cy='" << f.Y(s.y[i])
         << "' r='2.6' fill='" << s.color << "'><title>" << EscapeMarkup(s.name)
         << ", " << EscapeMarkup(chart.x_label) << ' ' << Fixed(chart.x[i], 0)
         << ": " << Fixed(s.y[i], 2) << (bar ? BarText(s.y[i], centre, w) : "")
         << "</title></circle>";
  }
  *out << "</g>";
}

}  // namespace

std::vector<double> RoundTicks(double low, double high, int count) {
  const double raw = (high - low) / std::max(1, count);
  if (!(raw > 0) || !std::isfinite(raw)) return {low};
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = power;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * power;
    if (step >= raw) break;
  }
  std::vector<double> ticks;
  for (double t = std::ceil(low / step - 1e-9) * step; t <= high + 1e-9 * step;
       t += step) {
    ticks.push_back(std::abs(t) < 1e-9 * step ? 0.0 : t);
  }
  return ticks;
}

std::string ChartSvg(const Chart& chart) {
  std::vector<const ChartSeries*> listed;
  for (const ChartSeries& s : chart.series) {
    if (s.legend) listed.push_back(&s);
  }
  // 100 px a legend entry ("10 mid 4", "GCS (global)").
  const int per_row = std::max(1, static_cast<int>(chart.width - kLeft) / 100);
  const int rows = (static_cast<int>(listed.size()) + per_row - 1) / per_row;
  const PlotArea f = PlotFrame(chart, rows);
  std::ostringstream out;
  out.precision(5);
  out << "<svg xmlns='http://www.w3.org/2000/svg' class='chart' width='"
      << chart.width << "' height='" << chart.height << "' viewBox='0 0 "
      << chart.width << ' ' << chart.height
      << "' font-family='sans-serif' font-size='11'>";
  Axes(chart, f, &out);
  Markers(chart, f, &out);
  for (const ChartSeries& s : chart.series) Curve(chart, s, f, &out);
  const double column = 100;
  for (size_t k = 0; k < listed.size(); ++k) {
    const double x = kLeft + (k % per_row) * column;
    const double y = f.bottom + kBottom + (k / per_row) * kLegendRow + 2;
    out << "<line x1='" << x << "' x2='" << x + 16 << "' y1='" << y - 4
        << "' y2='" << y - 4 << "' stroke='" << listed[k]->color
        << "' stroke-width='" << listed[k]->width << "'/><text x='" << x + 20
        << "' y='" << y << "'>" << EscapeMarkup(listed[k]->name) << "</text>";
  }
  out << "</svg>";
  return out.str();
}

}  // namespace pfdm
