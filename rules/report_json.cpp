#include "rules/report_json.h"

#include "core/atomic_file.h"
#include "rules/report_html.h"
#include "rules/report_markdown.h"
#include "rules/rule_catalog.h"

namespace mg {

nlohmann::json report_json(const Scenario& s, const CheckResult& r) {
  nlohmann::json j = check_result_to_json(r);
  j["scenario"] = {{"name", s.name}, {"description", s.description}};
  j["rule_catalog_version"] = rule_catalog_json().at("catalog_version");
  return j;
}

void write_check_reports(const std::string& dir, const Scenario& s, const CheckResult& r) {
  const std::string base = dir.empty() ? std::string(".") : dir;
  write_files_atomic({{base + "/report.json", report_json(s, r).dump(2) + "\n"},
                      {base + "/report.md", report_markdown(s, r)},
                      {base + "/report.html", report_html(s, r)}});
}

}  // namespace mg
