#include "report/report_table.h"

#include "report/svg_plot.h"

namespace mg {
namespace {

std::string html_cell(const std::string& cell) {
  const auto mid = cell.find("](");
  if (!cell.empty() && cell.front() == '[' && mid != std::string::npos && cell.back() == ')')
    return "<a href=\"" + html_escape(cell.substr(mid + 2, cell.size() - mid - 3)) + "\">" +
           html_escape(cell.substr(1, mid - 1)) + "</a>";
  return html_escape(cell);
}

}  // namespace

std::string html_escape(const std::string& s) { return svg::xml_escape(s); }

std::string inline_svg(std::string svg) {
  const std::string ns = " xmlns=\"http://www.w3.org/2000/svg\"";
  for (auto pos = svg.find(ns); pos != std::string::npos; pos = svg.find(ns)) svg.erase(pos, ns.size());
  return svg;
}

std::string table_markdown(const ReportTable& t) {
  std::string out = "|";
  for (const auto& h : t.header) out += " " + h + " |";
  out += "\n|";
  for (std::size_t i = 0; i < t.header.size(); ++i) out += "---|";
  out += "\n";
  for (const auto& row : t.rows) {
    out += "|";
    for (const auto& cell : row) out += " " + cell + " |";
    out += "\n";
  }
  return out;
}

std::string table_html(const ReportTable& t) {
  std::string out = "<table>\n<tr>";
  for (const auto& h : t.header) out += "<th>" + html_escape(h) + "</th>";
  out += "</tr>\n";
  for (const auto& row : t.rows) {
    out += "<tr>";
    for (const auto& cell : row) out += "<td>" + html_cell(cell) + "</td>";
    out += "</tr>\n";
  }
  return out + "</table>\n";
}

}  // namespace mg
