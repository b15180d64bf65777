#include "report/svg_plot.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

namespace mg::svg {
namespace {

TEST(SvgPlot, NiceTicksAreRoundAndCoverTheRange) {
  EXPECT_EQ(nice_ticks(0.0, 10.0, 5), (std::vector<double>{0, 2, 4, 6, 8, 10}));
  const auto t = nice_ticks(-0.021, 0.014, 6);
  ASSERT_GE(t.size(), 3u);
  EXPECT_GE(t.front(), -0.021);
  EXPECT_LE(t.back(), 0.014);
  EXPECT_NEAR(t[1] - t[0], 0.01, 1e-12);  // 0.035 / 6 = 0.0058 rounds up to 0.01
}

TEST(SvgPlot, RendersAxesLabelsLegendAndEscapedText) {
  Plot p;
  p.title = "Speed <ego> & obstacle";
  p.x_label = "time t [s]";
  p.y_label = "speed [m/s]";
  p.series.push_back({"ego", {0, 1, 2}, {20, 21, 22}, "#d62728", "4 2", 1.5});
  p.series.push_back({"", {0, 2}, {18, 18}, "#999999", "", 1.0});
  const std::string svg = render(p);
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_NE(svg.find("Speed &lt;ego&gt; &amp; obstacle"), std::string::npos);
  EXPECT_NE(svg.find("time t [s]"), std::string::npos);
  EXPECT_NE(svg.find("speed [m/s]"), std::string::npos);
  EXPECT_NE(svg.find(">ego</text>"), std::string::npos);
  EXPECT_NE(svg.find("stroke-dasharray=\"4 2\""), std::string::npos);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
}

TEST(SvgPlot, MarkersDrawAScatterAndTheLegendShowsThem) {
  Plot p;
  p.series.push_back({"points", {1, 2, NAN}, {1, 2, 3}, "#2ca02c", "", 1.0, 4.0});
  const std::string svg = render(p);
  std::size_t circles = 0;
  for (std::size_t at = svg.find("<circle"); at != std::string::npos; at = svg.find("<circle", at + 1)) ++circles;
  EXPECT_EQ(circles, 3u);  // two finite points and the legend's marker
  EXPECT_NE(svg.find("r=\"4.00\" fill=\"#2ca02c\""), std::string::npos);
  EXPECT_EQ(svg.find("stroke=\"#2ca02c\" stroke-width=\"1.40\""), std::string::npos);  // no legend line for it
  Plot lines;
  lines.series.push_back({"line", {1, 2}, {1, 2}, "#000", "", 1.0});
  EXPECT_EQ(render(lines).find("<circle"), std::string::npos);
  p.notes.push_back({2, 2, "b & c", "#2ca02c"});
  EXPECT_NE(render(p).find("fill=\"#2ca02c\">b &amp; c</text>"), std::string::npos);
  // A second note at the same point moves a line away instead of overlapping the first.
  p.notes.push_back({2, 2, "d", "#000000"});
  const std::string two = render(p);
  auto y_of = [&two](const std::string& text) {
    const std::size_t end = two.find(">" + text + "</text>");
    const std::size_t at = two.rfind(" y=\"", end);
    return std::stod(two.substr(at + 4));
  };
  EXPECT_NEAR(std::abs(y_of("d") - y_of("b &amp; c")), 14.0, 1e-9);
}

TEST(SvgPlot, NonFiniteValuesBreakTheLine) {
  Plot p;
  p.series.push_back({"s", {0, 1, 2, 3}, {0, 1, NAN, 3}, "#000", "", 1.0});
  const std::string svg = render(p);
  std::size_t moves = 0;
  for (std::size_t at = svg.find(" M"); at != std::string::npos; at = svg.find(" M", at + 1)) ++moves;
  EXPECT_EQ(moves, 2u);
}

TEST(SvgPlot, GridPlacesEveryPanel) {
  Plot a;
  a.title = "panel A";
  Plot b;
  b.title = "panel B";
  const std::string svg = render_grid({a, b, a}, 2, "All");
  EXPECT_NE(svg.find("panel B"), std::string::npos);
  EXPECT_NE(svg.find("width=\"1280\""), std::string::npos);
  EXPECT_NE(svg.find(">All</text>"), std::string::npos);
}

TEST(SvgPlot, ARangeBandCoversOnlyItsRangeAndWidensTheAxis) {
  Plot p;
  p.width_px = 300;  // axes x from 72 (kMarginLeft) to 284
  p.series.push_back({"s", {0, 10}, {20, 30}, "#000", "", 1.0});
  p.bands.push_back({-INFINITY, INFINITY, "paper: below 10", "#cfe8cf", Range{0.0, 10.0}});
  const std::string svg = render(p);
  EXPECT_NE(svg.find("paper: below 10"), std::string::npos);
  // The y axis reaches down to the band although no data does: a tick at 0 is drawn.
  EXPECT_NE(svg.find(">0</text>"), std::string::npos);
  const std::size_t rect = svg.find("fill=\"#cfe8cf\"");
  ASSERT_NE(rect, std::string::npos);
  const std::size_t start = svg.rfind("<rect", rect);
  const std::string tag = svg.substr(start, rect - start);
  EXPECT_EQ(tag.find("height=\"0.00\""), std::string::npos) << tag;
  EXPECT_NE(tag.find("x=\"72.00\""), std::string::npos) << "an infinite band starts at the axis: " << tag;
}

TEST(SvgPlot, ThinningLeavesASeriesThatFitsUnchanged) {
  Series s{"s", {}, {}, "#000", "", 1.0};
  for (int i = 0; i < 40; ++i) s.x.push_back(i), s.y.push_back(std::sin(i));
  const Series t = thinned(s, {0.0, 39.0}, 10);  // 40 points, 4 per column: all shown
  EXPECT_EQ(t.x, s.x);
  EXPECT_EQ(t.y, s.y);
}

// M4: of every unbroken run of points in one column, the first, lowest, highest and last point
// survive, in order, as a subsequence of the series; breaks stay breaks.
RC_GTEST_PROP(SvgPlot, ThinningKeepsEachColumnsEndsAndExtremesInOrder, ()) {
  const int columns = *rc::gen::inRange(1, 30);
  const auto n = *rc::gen::inRange<std::size_t>(0, 2000);
  Series s{"s", {}, {}, "#000", "", 1.0};
  for (std::size_t i = 0; i < n; ++i) {
    s.x.push_back(static_cast<double>(i) * 0.01);
    s.y.push_back(*rc::gen::inRange(0, 30) == 0 ? NAN : *rc::gen::inRange(-1000, 1000) * 0.1);
  }
  const Range xr{0.0, std::max(0.01, static_cast<double>(n) * 0.01)};
  const Series t = thinned(s, xr, columns);
  RC_ASSERT(t.x.size() == t.y.size());
  if (n <= 4 * static_cast<std::size_t>(columns)) RC_SUCCEED("unchanged");
  RC_ASSERT(t.x.size() <= n);
  // Every finite kept point is an original point, in order.
  std::size_t at = 0;
  for (std::size_t k = 0; k < t.x.size(); ++k) {
    if (std::isnan(t.y[k])) continue;
    while (at < n && !(s.x[at] == t.x[k] && s.y[at] == t.y[k])) ++at;
    RC_ASSERT(at < n);
  }
  // Every run's extremes are kept.
  const double scale = columns / (xr.hi - xr.lo);  // as the thinner computes it: same rounding
  auto column = [&](double x) { return std::clamp(static_cast<long>(std::floor((x - xr.lo) * scale)), 0L, static_cast<long>(columns) - 1); };
  for (std::size_t i = 0; i < n;) {
    if (std::isnan(s.y[i])) { ++i; continue; }
    std::size_t j = i;
    double lo = s.y[i], hi = s.y[i];
    while (j < n && !std::isnan(s.y[j]) && column(s.x[j]) == column(s.x[i])) lo = std::min(lo, s.y[j]), hi = std::max(hi, s.y[j]), ++j;
    for (double want : {lo, hi, s.y[i], s.y[j - 1]}) {
      bool found = false;
      for (std::size_t k = 0; k < t.x.size(); ++k) found = found || (t.y[k] == want && t.x[k] >= s.x[i] && t.x[k] <= s.x[j - 1]);
      RC_ASSERT(found);
    }
    i = j;
  }
}

TEST(SvgPlot, APlotOfManyLongSeriesRendersWithinThePointBudget) {
  Plot p;
  p.width_px = 960;
  for (int k = 0; k < 130; ++k) {
    Series s{"", {}, {}, "#000", "", 1.0};
    for (int i = 0; i < 30000; ++i) s.x.push_back(i * 0.02), s.y.push_back(std::sin(i * 0.001 * (k + 1)));
    p.series.push_back(std::move(s));
  }
  const std::string svg = render(p);
  std::size_t points = 0;
  for (char c : svg) points += c == 'L' || c == 'M';
  EXPECT_LE(points, kMaxPointsPerPlot + 8);
  EXPECT_LT(svg.size(), 600u * 1024u);
}

}  // namespace
}  // namespace mg::svg
