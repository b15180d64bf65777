// A small, dependency-free SVG line-plot writer for reports: axes with "nice" ticks, axis
// labels with units, a legend, polylines with colour and dash pattern, optional shaded bands.
// Output is a standalone SVG document; several panels can share one document (a grid).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace mg::svg {

struct Series {
  std::string label;               // legend entry; empty = not in the legend
  std::vector<double> x, y;        // same length; non-finite points break the line
  std::string colour = "#1f77b4";
  std::string dash;                // SVG stroke-dasharray, e.g. "6 3"; empty = solid
  double width_px = 1.6;
  // > 0: a filled circle of this radius at every finite point (a scatter plot's points), which
  // the legend then shows instead of a line.
  double marker_radius_px = 0.0;
};

struct Range {
  double lo = 0.0, hi = 1.0;
};

// A shaded vertical band [x_from, x_to] with a caption (e.g. the merge manoeuvre); with y, only
// the rectangle [x_from, x_to] x [y.lo, y.hi] (e.g. a range a paper reports; x_from = -inf and
// x_to = +inf span the axes).
struct Band {
  double x_from = 0.0, x_to = 0.0;
  std::string caption;
  std::string colour = "#f2e6b3";
  std::optional<Range> y;
};

enum class LegendCorner { kTopRight, kBottomRight, kTopLeft, kBottomLeft };

// A text beside a data point (a scatter plot's names), in the point's colour, starting just right
// of it, vertically centred on it; a line up or down where it would overlap another note or a
// marker.
struct PointNote {
  double x = 0.0, y = 0.0;
  std::string text;
  std::string colour = "#333333";
};

struct Plot {
  std::string title;
  std::string x_label;             // with unit, e.g. "time t [s]"
  std::string y_label;
  std::vector<Series> series;
  std::vector<Band> bands;
  std::vector<PointNote> notes;
  std::optional<Range> x_range;    // default: data extent
  std::optional<Range> y_range;    // default: data extent with 5 % padding
  LegendCorner legend = LegendCorner::kTopRight;  // inside the axes, on a white box
  int width_px = 640;
  int height_px = 360;
};

// A plot's frame: title, axis labels (with units) and size; its series, bands, ranges and legend
// are filled in after. Every report's plot starts here.
Plot frame(std::string title, std::string x_label, std::string y_label, int width_px, int height_px);

// What a plot `columns` pixels wide shows of `s` over `x_range` (M4 thinning): of every unbroken
// run of points in one column, its first, lowest, highest and last point, in order; line breaks
// (non-finite points) are kept. A series of at most 4 x columns points is returned unchanged.
Series thinned(const Series& s, Range x_range, int columns);

// thinned() one point at a time, for series too long to hold (a report's plot of a long trace):
// add the points in order, then take() the thinned series. It always thins: the size test of
// thinned() is the caller's.
class Thinner {
 public:
  Thinner(Series style, Range x_range, int columns);
  void add(double x, double y);
  Series take();

 private:
  void keep_run();
  Series out_;
  double lo_ = 0.0, scale_ = 0.0;
  long columns_ = 1;
  bool in_run_ = false;
  long run_column_ = 0;
  double run_x_[4] = {}, run_y_[4] = {};  // first, lowest, highest, last
  std::size_t run_index_[4] = {};
  std::size_t next_ = 0;
};

// render() thins a plot whose series hold more points than this, so that a report stays a few
// megabytes for any scene (64 vehicles, an hour): each series keeps what its share of the
// budget shows.
inline constexpr std::size_t kMaxPointsPerPlot = 24000;

// Round tick values ("1, 2, 5 x 10^k" steps) covering [lo, hi], about `target` of them.
std::vector<double> nice_ticks(double lo, double hi, int target = 6);

// Escapes &, <, > and " for XML/HTML text and attribute values.
std::string xml_escape(const std::string& s);

// One plot as a standalone SVG document.
std::string render(const Plot& plot);

// Several plots in a grid (row-major) in one SVG document with an overall title.
std::string render_grid(const std::vector<Plot>& plots, int columns, const std::string& title = "");

}  // namespace mg::svg
