#include "report/report_json.h"

#include "core/atomic_file.h"
#include "report/report_html.h"
#include "report/report_markdown.h"
#include "rules/rule_catalog.h"

namespace mg {

nlohmann::json report_json(const CheckResult& r) {
  nlohmann::json j = check_result_to_json(r);
  j["scenario"] = {{"name", r.trace.name}, {"source", r.trace.source}};
  j["rule_catalog_version"] = rule_catalog_json().at("catalog_version");
  return j;
}

void write_check_reports(const std::string& dir, const CheckResult& r) {
  const std::string base = dir.empty() ? std::string(".") : dir;
  write_files_atomic({{base + "/report.json", report_json(r).dump(2) + "\n"},
                      {base + "/report.md", report_markdown(r)},
                      {base + "/report.html", report_html(r)}});
}

}  // namespace mg
