#include "report/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <limits>
#include <sstream>
#include <utility>

#include "core/fixed_text.h"

namespace mg::svg {

Plot frame(std::string title, std::string x_label, std::string y_label, int width_px, int height_px) {
  Plot p;
  p.title = std::move(title);
  p.x_label = std::move(x_label);
  p.y_label = std::move(y_label);
  p.width_px = width_px;
  p.height_px = height_px;
  return p;
}

namespace {

constexpr int kMarginLeft = 72, kMarginRight = 16, kMarginTop = 34, kMarginBottom = 50;
constexpr int kGridTitleHeight = 36;


std::string num(double v) { return fixed_text(v, 2); }

std::string tick_label(double v, double step) {
  int decimals = 0;  // as many as the step needs: 2.5 -> 1, 0.02 -> 2
  for (double scaled = step; decimals < 6 && std::abs(scaled - std::round(scaled)) > 1e-6 * scaled; scaled *= 10.0)
    ++decimals;
  return fixed_text(std::abs(v) < step * 1e-9 ? 0.0 : v, decimals);
}

Range data_range(const Plot& p, bool x_axis) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Series& s : p.series)
    for (double v : x_axis ? s.x : s.y)
      if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  if (!x_axis)  // a range band must be seen even where no data reaches it
    for (const Band& b : p.bands)
      if (b.y && std::isfinite(b.y->lo) && std::isfinite(b.y->hi)) lo = std::min(lo, b.y->lo), hi = std::max(hi, b.y->hi);
  if (!std::isfinite(lo)) return {0.0, 1.0};
  if (hi - lo < 1e-12) return {lo - 1.0, hi + 1.0};
  if (!x_axis) {
    const double pad = 0.05 * (hi - lo);
    return {lo - pad, hi + pad};
  }
  return {lo, hi};
}

// The plot's series, thinned to kMaxPointsPerPlot points in all when they hold more.
std::vector<Series> shown_series(const Plot& p, Range xr) {
  constexpr std::size_t kShort = 32;  // outlines and reference lines: kept whole
  std::size_t points = 0, short_points = 0, long_series = 0;
  for (const Series& s : p.series) {
    const std::size_t k = std::min(s.x.size(), s.y.size());
    points += k;
    if (k <= kShort) short_points += k;
    else ++long_series;
  }
  if (points <= kMaxPointsPerPlot || long_series == 0) return p.series;
  const std::size_t left = kMaxPointsPerPlot > short_points ? kMaxPointsPerPlot - short_points : 0;
  const int columns = static_cast<int>(std::max<std::size_t>(kShort / 4, left / (4 * long_series)));
  std::vector<Series> out;
  out.reserve(p.series.size());
  for (const Series& s : p.series) out.push_back(thinned(s, xr, std::min(columns, p.width_px)));
  return out;
}

// The series, clipped to the axes; px and py map data to pixels.
void draw_series(std::ostringstream& out, const Plot& p, Range xr, int ox, int oy, const std::function<double(double)>& px,
                 const std::function<double(double)>& py) {
  for (const Series& s : shown_series(p, xr)) {
    std::string d;
    bool pen_down = false;
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) {
        pen_down = false;
        continue;
      }
      d += (pen_down ? " L" : " M") + num(px(s.x[i])) + " " + num(py(s.y[i]));
      pen_down = true;
    }
    if (d.empty()) continue;
    out << "<path clip-path=\"url(#clip" << ox << "_" << oy << ")\" d=\"" << d << "\" fill=\"none\" stroke=\""
        << s.colour << "\" stroke-width=\"" << num(s.width_px) << "\"";
    if (!s.dash.empty()) out << " stroke-dasharray=\"" << s.dash << "\"";
    out << "/>\n";
    if (s.marker_radius_px <= 0.0) continue;
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i)
      if (std::isfinite(s.x[i]) && std::isfinite(s.y[i]))
        out << "<circle clip-path=\"url(#clip" << ox << "_" << oy << ")\" cx=\"" << num(px(s.x[i])) << "\" cy=\""
            << num(py(s.y[i])) << "\" r=\"" << num(s.marker_radius_px) << "\" fill=\"" << s.colour << "\"/>\n";
  }
}

// The notes beside their points. A note that would overlap an earlier one or a marker moves up or
// down by a line (the nearest free place of a few), so that close points keep legible names.
void draw_notes(std::ostringstream& out, const Plot& p, const std::function<double(double)>& px,
                const std::function<double(double)>& py) {
  constexpr double kCharWidthPx = 7.0, kLineHeightPx = 14.0;  // 12 px sans-serif
  struct Box {
    double x0, y0, x1, y1;
    bool meets(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
  };
  std::vector<Box> taken;
  for (const Series& s : p.series)
    if (s.marker_radius_px > 0.0)
      for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i)
        if (std::isfinite(s.x[i]) && std::isfinite(s.y[i])) {
          const double r = s.marker_radius_px;
          taken.push_back({px(s.x[i]) - r, py(s.y[i]) - r, px(s.x[i]) + r, py(s.y[i]) + r});
        }
  for (const PointNote& n : p.notes) {
    if (!std::isfinite(n.x) || !std::isfinite(n.y)) continue;
    const double x = px(n.x) + 9, width = kCharWidthPx * static_cast<double>(n.text.size());
    double y = py(n.y) + 4;  // the baseline
    for (const double shift : {0.0, -1.0, 1.0, -2.0, 2.0, -3.0, 3.0}) {
      const double candidate = py(n.y) + 4 + shift * kLineHeightPx;
      const Box box{x, candidate - 10, x + width, candidate + 2};
      if (std::none_of(taken.begin(), taken.end(), [&](const Box& b) { return b.meets(box); })) {
        y = candidate;
        break;
      }
    }
    taken.push_back({x, y - 10, x + width, y + 2});
    out << "<text x=\"" << num(x) << "\" y=\"" << num(y) << "\" font-size=\"12\" fill=\"" << n.colour << "\">"
        << xml_escape(n.text) << "</text>\n";
  }
}

// The legend inside the axes [x0, x1] x [y1, y0] (y0 the bottom edge), on a white box so that it
// stays readable over the data.
void draw_legend(std::ostringstream& out, const Plot& p, double x0, double x1, double y0, double y1) {
  int entries = 0;
  for (const Series& s : p.series) entries += s.label.empty() ? 0 : 1;
  if (entries > 0) {
    constexpr double kBoxW = 200.0, kRowH = 16.0;
    const double box_h = 8.0 + kRowH * entries;
    const bool right = p.legend == LegendCorner::kTopRight || p.legend == LegendCorner::kBottomRight;
    const bool top = p.legend == LegendCorner::kTopRight || p.legend == LegendCorner::kTopLeft;
    const double bx = right ? x1 - kBoxW - 6 : x0 + 6, by = top ? y1 + 6 : y0 - box_h - 6;
    out << "<rect x=\"" << num(bx) << "\" y=\"" << num(by) << "\" width=\"" << num(kBoxW) << "\" height=\""
        << num(box_h) << "\" fill=\"white\" fill-opacity=\"0.85\" stroke=\"#bbb\"/>\n";
    int row = 0;
    for (const Series& s : p.series) {
      if (s.label.empty()) continue;
      const double ly = by + 12 + kRowH * row++, lx = bx + 6;
      if (s.marker_radius_px > 0.0) {
        out << "<circle cx=\"" << num(lx + 14) << "\" cy=\"" << num(ly) << "\" r=\"" << num(s.marker_radius_px)
            << "\" fill=\"" << s.colour << "\"/>\n";
      } else {
        out << "<line x1=\"" << num(lx) << "\" y1=\"" << num(ly) << "\" x2=\"" << num(lx + 28) << "\" y2=\"" << num(ly)
            << "\" stroke=\"" << s.colour << "\" stroke-width=\"" << num(s.width_px + 0.4) << "\"";
        if (!s.dash.empty()) out << " stroke-dasharray=\"" << s.dash << "\"";
        out << "/>\n";
      }
      out << "<text x=\"" << num(lx + 34) << "\" y=\"" << num(ly + 4) << "\" font-size=\"11\">" << xml_escape(s.label)
          << "</text>\n";
    }
  }
}

// Draws one plot into `out` with its top-left corner at (ox, oy).
void draw(std::ostringstream& out, const Plot& p, int ox, int oy) {
  const Range xr = p.x_range.value_or(data_range(p, true));
  const Range yr = p.y_range.value_or(data_range(p, false));
  const double x0 = ox + kMarginLeft, x1 = ox + p.width_px - kMarginRight;
  const double y0 = oy + p.height_px - kMarginBottom, y1 = oy + kMarginTop;  // y0 bottom
  auto px = [&](double x) { return x0 + (x - xr.lo) / (xr.hi - xr.lo) * (x1 - x0); };
  auto py = [&](double y) { return y0 - (y - yr.lo) / (yr.hi - yr.lo) * (y0 - y1); };

  out << "<g font-family=\"sans-serif\" font-size=\"12\">\n";
  out << "<text x=\"" << num(0.5 * (x0 + x1)) << "\" y=\"" << oy + 20
      << "\" text-anchor=\"middle\" font-size=\"14\" font-weight=\"bold\">" << xml_escape(p.title) << "</text>\n";
  out << "<clipPath id=\"clip" << ox << "_" << oy << "\"><rect x=\"" << num(x0) << "\" y=\"" << num(y1)
      << "\" width=\"" << num(x1 - x0) << "\" height=\"" << num(y0 - y1) << "\"/></clipPath>\n";
  for (const Band& b : p.bands) {
    const double bx0 = std::clamp(px(b.x_from), x0, x1), bx1 = std::clamp(px(b.x_to), x0, x1);
    // y0 is the bottom edge: a band's top is the smaller pixel value.
    const double top = b.y ? std::clamp(py(b.y->hi), y1, y0) : y1, bottom = b.y ? std::clamp(py(b.y->lo), y1, y0) : y0;
    out << "<rect x=\"" << num(bx0) << "\" y=\"" << num(top) << "\" width=\"" << num(bx1 - bx0) << "\" height=\""
        << num(bottom - top) << "\" fill=\"" << b.colour << "\" opacity=\"0.6\"/>\n";
    if (b.y)  // a range band: captioned at its left end, inside it
      out << "<text x=\"" << num(bx0 + 4) << "\" y=\"" << num(std::min(bottom - 3, top + 11))
          << "\" font-size=\"10\" fill=\"#554\">" << xml_escape(b.caption) << "</text>\n";
    else
      out << "<text x=\"" << num(0.5 * (bx0 + bx1)) << "\" y=\"" << num(y1 + 14)
          << "\" text-anchor=\"middle\" font-size=\"11\" fill=\"#665\">" << xml_escape(b.caption) << "</text>\n";
  }
  // Grid, ticks and tick labels.
  const auto xt = nice_ticks(xr.lo, xr.hi), yt = nice_ticks(yr.lo, yr.hi);
  const double xstep = xt.size() > 1 ? xt[1] - xt[0] : 1.0, ystep = yt.size() > 1 ? yt[1] - yt[0] : 1.0;
  for (double t : xt) {
    out << "<line x1=\"" << num(px(t)) << "\" y1=\"" << num(y0) << "\" x2=\"" << num(px(t)) << "\" y2=\"" << num(y1)
        << "\" stroke=\"#e4e4e4\"/>\n";
    out << "<text x=\"" << num(px(t)) << "\" y=\"" << num(y0 + 16) << "\" text-anchor=\"middle\">"
        << tick_label(t, xstep) << "</text>\n";
  }
  for (double t : yt) {
    out << "<line x1=\"" << num(x0) << "\" y1=\"" << num(py(t)) << "\" x2=\"" << num(x1) << "\" y2=\"" << num(py(t))
        << "\" stroke=\"#e4e4e4\"/>\n";
    out << "<text x=\"" << num(x0 - 6) << "\" y=\"" << num(py(t) + 4) << "\" text-anchor=\"end\">"
        << tick_label(t, ystep) << "</text>\n";
  }
  out << "<rect x=\"" << num(x0) << "\" y=\"" << num(y1) << "\" width=\"" << num(x1 - x0) << "\" height=\""
      << num(y0 - y1) << "\" fill=\"none\" stroke=\"#333\"/>\n";
  out << "<text x=\"" << num(0.5 * (x0 + x1)) << "\" y=\"" << num(y0 + 36) << "\" text-anchor=\"middle\">"
      << xml_escape(p.x_label) << "</text>\n";
  out << "<text transform=\"translate(" << ox + 16 << "," << num(0.5 * (y0 + y1))
      << ") rotate(-90)\" text-anchor=\"middle\">" << xml_escape(p.y_label) << "</text>\n";
  draw_series(out, p, xr, ox, oy, px, py);
  draw_notes(out, p, px, py);
  draw_legend(out, p, x0, x1, y0, y1);
  out << "</g>\n";
}

std::string header(int w, int h) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(w) + "\" height=\"" +
         std::to_string(h) + "\" viewBox=\"0 0 " + std::to_string(w) + " " + std::to_string(h) +
         "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
}

}  // namespace

Thinner::Thinner(Series style, Range x_range, int columns) : out_(std::move(style)), lo_(x_range.lo) {
  out_.x.clear();
  out_.y.clear();
  columns_ = std::max(columns, 1);
  const double width = x_range.hi - x_range.lo;
  scale_ = width > 0.0 && std::isfinite(width) ? static_cast<double>(columns_) / width : 0.0;
}

void Thinner::add(double x, double y) {
  const std::size_t i = next_++;
  if (!std::isfinite(x) || !std::isfinite(y)) {
    if (in_run_) {  // one break marker per break
      keep_run();
      out_.x.push_back(x);
      out_.y.push_back(std::nan(""));
    }
    in_run_ = false;
    return;
  }
  const long c = std::clamp(static_cast<long>(std::floor((x - lo_) * scale_)), 0L, columns_ - 1);
  if (in_run_ && c == run_column_) {
    if (y < run_y_[1]) run_x_[1] = x, run_y_[1] = y, run_index_[1] = i;
    if (y > run_y_[2]) run_x_[2] = x, run_y_[2] = y, run_index_[2] = i;
    run_x_[3] = x, run_y_[3] = y, run_index_[3] = i;
    return;
  }
  if (in_run_) keep_run();
  in_run_ = true;
  run_column_ = c;
  for (int k = 0; k < 4; ++k) run_x_[k] = x, run_y_[k] = y, run_index_[k] = i;
}

// The run's first, lowest, highest and last point, in their order, each once.
void Thinner::keep_run() {
  int order[4] = {0, 1, 2, 3};
  std::sort(std::begin(order), std::end(order), [this](int a, int b) { return run_index_[a] < run_index_[b]; });
  for (int k = 0; k < 4; ++k) {
    if (k > 0 && run_index_[order[k]] == run_index_[order[k - 1]]) continue;
    out_.x.push_back(run_x_[order[k]]);
    out_.y.push_back(run_y_[order[k]]);
  }
}

Series Thinner::take() {
  if (in_run_) keep_run();
  in_run_ = false;
  return std::move(out_);
}

Series thinned(const Series& s, Range x_range, int columns) {
  const std::size_t n = std::min(s.x.size(), s.y.size());
  if (columns < 1 || n <= 4 * static_cast<std::size_t>(columns)) return s;
  Thinner t(s, x_range, columns);
  for (std::size_t i = 0; i < n; ++i) t.add(s.x[i], s.y[i]);
  return t.take();
}

std::vector<double> nice_ticks(double lo, double hi, int target) {
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return {lo};
  const double raw = (hi - lo) / std::max(target, 1);
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = mag;
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * mag >= raw) {
      step = m * mag;
      break;
    }
  std::vector<double> ticks;
  for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + step * 1e-9; t += step) ticks.push_back(t);
  return ticks;
}

std::string render(const Plot& plot) {
  std::ostringstream out;
  out << header(plot.width_px, plot.height_px);
  draw(out, plot, 0, 0);
  out << "</svg>\n";
  return out.str();
}

std::string render_grid(const std::vector<Plot>& plots, int columns, const std::string& title) {
  columns = std::max(columns, 1);
  int cell_w = 0, cell_h = 0;
  for (const Plot& p : plots) cell_w = std::max(cell_w, p.width_px), cell_h = std::max(cell_h, p.height_px);
  const int rows = (static_cast<int>(plots.size()) + columns - 1) / columns;
  const int top = title.empty() ? 0 : kGridTitleHeight;
  std::ostringstream out;
  out << header(cell_w * columns, top + cell_h * rows);
  if (!title.empty())
    out << "<text x=\"" << cell_w * columns / 2 << "\" y=\"24\" text-anchor=\"middle\" font-family=\"sans-serif\" "
        << "font-size=\"16\" font-weight=\"bold\">" << xml_escape(title) << "</text>\n";
  for (std::size_t i = 0; i < plots.size(); ++i)
    draw(out, plots[i], static_cast<int>(i % columns) * cell_w, top + static_cast<int>(i / columns) * cell_h);
  out << "</svg>\n";
  return out.str();
}

std::string xml_escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace mg::svg
