// The audit's HTML pages: index.html and each merge's audit.html, self-contained
// (inline CSS and SVG), with the same content as the Markdown pages (audit_report.h).
#pragma once

#include <string>

#include "audit/recording_audit.h"

namespace mg {

std::string audit_index_html(const RecordingAudit& a);
std::string merge_audit_html(const RecordingAudit& a, std::size_t i);

}  // namespace mg
