#include "sim/svg_plot.h"

#include <cmath>

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace mg::svg
