// The audit's HTML pages: index.html and each merge's audit.html, self-contained
// (inline CSS and SVG), with the same content as the Markdown pages (audit_report.h).
#pragma once

#include <map>
#include <string>

#include "audit/recording_audit.h"

namespace mg {

std::string audit_index_html(const RecordingAudit& a);
// A page from the audit's Markdown (the subset its pages use: headings, lists, tables, links,
// images named in `svgs` inlined).
std::string audit_page_html(const std::string& title, const std::string& md, const std::map<std::string, std::string>& svgs);
std::string merge_audit_html(const RecordingAudit& a, std::size_t i);

}  // namespace mg
