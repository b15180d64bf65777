// A report's table as rows of cells, rendered to Markdown or HTML from the same rows, so that a
// report's .md and .html say the same thing. Cells are plain text; a cell that is a Markdown link
// "[text](href)" becomes an anchor in HTML.
#pragma once

#include <string>
#include <vector>

namespace mg {

struct ReportTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

std::string table_markdown(const ReportTable& t);
std::string table_html(const ReportTable& t);

// Escapes &, <, > and " for HTML text and attribute values.
std::string html_escape(const std::string& s);

// An SVG document to inline in an HTML page: the namespace declaration is dropped (inline SVG
// needs none), so that the page holds no URL.
std::string inline_svg(std::string svg);

}  // namespace mg
