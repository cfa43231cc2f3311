// Curves over the cycle as inline SVG, each point's value shown on hover
// (an SVG <title>), with ED and ES marked: the report's own small charts
// where gnuplot's SVG could only name its curves "gnuplot_plot_1a".
#ifndef PFDM_REPORT_SVG_CHART_H_
#define PFDM_REPORT_SVG_CHART_H_

#include <string>
#include <vector>

namespace pfdm {

struct ChartSeries {
  std::string name;       // On hover, and in the legend.
  std::vector<double> y;  // One per x; NaN: a gap.
  std::string color;      // CSS colour.
  double width = 1.5;
  bool legend = true;  // Listed in the legend (many curves: hover only).
  // Per value, a 95 % half-width drawn as an error bar and given on hover;
  // empty: none.  (The {} lets a series' brace initializer leave it and
  // `bias` out without -Wmissing-field-initializers.)
  std::vector<double> half_width{};
  // Per value, the bias the noise puts into it (report/local_field_noise.h):
  // the bar is centred on y - bias, as fit.json's ci95 is, so it can miss
  // the dot.  Empty or NaN: centred on y.
  std::vector<double> bias{};
};

struct Chart {
  std::string title;
  std::string x_label;  // "time from the trigger (ms)" or "frame".
  std::string y_label;  // Units included.
  std::vector<double> x;
  std::vector<ChartSeries> series;
  int ed = -1, es = -1;  // Indices into x marked by a line; -1: none.
  bool zero_line = false;
  int width = 400, height = 280;
};

// Axes with round ticks, the curves, a dot per value whose <title> reads
// "NAME, X_LABEL X: Y", dashed lines at ED and ES labelled above the plot
// (where nothing else is), the legend under it.  Text is escaped.
std::string ChartSvg(const Chart& chart);

// Round tick values covering [low, high], about `count` of them.
std::vector<double> RoundTicks(double low, double high, int count);

}  // namespace pfdm

#endif  // PFDM_REPORT_SVG_CHART_H_
