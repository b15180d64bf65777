#include "audit/audit_html.h"

#include <map>
#include <regex>
#include <sstream>

#include "audit/audit_plots.h"
#include "audit/audit_report.h"
#include "report/svg_plot.h"

namespace mg {
namespace {

// Inline Markdown of the audit pages (the subset they use): **bold**, `code`, [text](href).
std::string inline_html(const std::string& md) {
  std::string s = svg::xml_escape(md);
  s = std::regex_replace(s, std::regex(R"(\*\*([^*]+)\*\*)"), "<b>$1</b>");
  s = std::regex_replace(s, std::regex("`([^`]+)`"), "<code>$1</code>");
  s = std::regex_replace(s, std::regex(R"(\[([^\]]+)\]\(([^)]+)\))"), "<a href=\"$2\">$1</a>");
  return s;
}

std::string table_row(const std::string& line, bool header) {
  std::string out = "<tr>";
  std::stringstream cells(line.substr(1));
  std::string cell;
  while (std::getline(cells, cell, '|')) {
    if (cell.find_first_not_of(' ') == std::string::npos && cells.eof()) break;
    out += (header ? "<th>" : "<td>") + inline_html(cell) + (header ? "</th>" : "</td>");
  }
  return out + "</tr>\n";
}

// The page's Markdown as HTML; images named in `svgs` are inlined.
std::string page(const std::string& title, const std::string& md, const std::map<std::string, std::string>& svgs) {
  std::string body;
  std::stringstream in(md);
  std::string line;
  bool in_list = false, in_table = false, header = false;
  while (std::getline(in, line)) {
    const bool item = line.rfind("- ", 0) == 0, row = line.rfind("|", 0) == 0;
    if (in_list && !item) body += "</ul>\n", in_list = false;
    if (in_table && !row) body += "</table>\n", in_table = false;
    if (line.rfind("# ", 0) == 0) {
      body += "<h1>" + inline_html(line.substr(2)) + "</h1>\n";
    } else if (line.rfind("## ", 0) == 0) {
      body += "<h2>" + inline_html(line.substr(3)) + "</h2>\n";
    } else if (item) {
      if (!in_list) body += "<ul>\n", in_list = true;
      body += "<li>" + inline_html(line.substr(2)) + "</li>\n";
    } else if (row) {
      if (!in_table) body += "<table>\n", in_table = true, header = true;
      if (line.rfind("|---", 0) == 0) continue;
      body += table_row(line, header);
      header = false;
    } else if (line.rfind("![", 0) == 0) {
      const std::string file = line.substr(line.find('(') + 1, line.find(')') - line.find('(') - 1);
      if (svgs.count(file)) body += "<div class=\"plot\">" + svgs.at(file) + "</div>\n";
    } else if (!line.empty()) {
      body += "<p>" + inline_html(line) + "</p>\n";
    }
  }
  if (in_list) body += "</ul>\n";
  if (in_table) body += "</table>\n";
  return "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" + svg::xml_escape(title) +
         "</title><style>body{font-family:sans-serif;max-width:1100px;margin:2em auto}table{border-collapse:collapse}"
         "td,th{border:1px solid #ccc;padding:3px 6px;font-size:90%}code{background:#f4f4f4}</style></head><body>\n" +
         body + "</body></html>\n";
}

}  // namespace

std::string audit_page_html(const std::string& title, const std::string& md, const std::map<std::string, std::string>& svgs) {
  return page(title, md, svgs);
}

std::string audit_index_html(const RecordingAudit& a) {
  std::string md = audit_index_markdown(a);
  md = std::regex_replace(md, std::regex(R"((\]\([^)\s]*)/audit\.md\))"), "$1/audit.html)");
  return page("Audit of " + a.recording->benchmark_id, md, {});
}

std::string merge_audit_html(const RecordingAudit& a, std::size_t i) {
  std::string md = merge_audit_markdown(a, i);
  md = std::regex_replace(md, std::regex(R"(\[report\.md\]\(report\.md\), )"), "");
  const MergeAudit& m = a.merges[i];
  std::map<std::string, std::string> svgs{{"road.svg", road_shape_svg(a, m)}, {"frenet.svg", curvilinear_svg(m)}};
  if (m.frontier) svgs["frontier.svg"] = frontier_svg(m);
  return page(m.merge.trace.name, md, svgs);
}

}  // namespace mg
