#include "report/report_markdown.h"


#include <cmath>
#include <sstream>

#include "core/fixed_text.h"
#include "rules/planner_account.h"
#include "rules/rule_catalog.h"

namespace mg {

std::string format_number(double v, int decimals) {
  if (!std::isfinite(v)) return "-";
  return fixed_text(v, decimals);
}

namespace {

std::string cell(std::string s) {
  for (char& c : s) {
    if (c == '|' || c == '\n') c = ' ';
  }
  return s;
}

}  // namespace

std::string report_markdown(const CheckResult& r) {
  const ObservedTrace& s = r.trace;
  std::ostringstream md;
  md << "# mergeguard liability report: " << s.name << "\n\n"
     << "**Verdict: " << (r.holds ? "HOLDS" : "VIOLATED") << "** - liable: **" << party_name(r.liable_id) << "**"
     << (r.collision ? " - collision (liable: " + party_name(r.collision_liable_id) + ")" : "") << "\n\n";
  if (!r.liability_detail.empty()) md << r.liability_detail << "\n\n";
  md << "Planner: `" << r.planner << "`. Trace from " << s.source << ".\n\n";
  md << "## Violations\n\n";
  bool any = false;
  for (const RuleResult& rule : r.rules) {
    if (rule.holds) continue;
    if (!any) {
      md << "| rule | paper reference | liable | first violation [s] | required | actual | margin | at [s] | what happened |\n"
         << "|---|---|---|---|---|---|---|---|---|\n";
    }
    any = true;
    md << "| " << rule.rule_id << " | " << cell(rule.paper_ref) << " | " << party_name(rule.liable_id) << " | "
       << format_number(*rule.first_violation_time_s, 2) << " | " << format_number(rule.required_value) << " "
       << rule.unit << " | " << format_number(rule.actual_value) << " " << rule.unit << " | "
       << format_number(rule.min_margin) << " " << rule.unit << " | " << format_number(rule.min_margin_time_s, 2)
       << " | " << cell(rule.detail) << " |\n";
  }
  if (!any) md << "None: every rule holds.\n";
  md << "\n## Right of way\n\n";
  for (const auto& [t, holder] : r.right_of_way) {
    md << "- from t = " << format_number(t, 2) << " s: " << party_name(holder) << "\n";
  }
  for (const std::string& o : r.right_of_way_observations) md << "- observed: " << o << "\n";
  md << "\n## All rules\n\n| rule | paper reference | holds | min margin | at [s] | statement |\n|---|---|---|---|---|---|\n";
  for (const RuleResult& rule : r.rules) {
    md << "| " << rule.rule_id << " | " << cell(rule.paper_ref) << " | " << (rule.holds ? "yes" : "**no**") << " | "
       << (std::isfinite(rule.min_margin) ? format_number(rule.min_margin) + " " + rule.unit : "n/a") << " | "
       << format_number(rule.min_margin_time_s, 2) << " | " << cell(rule_spec(rule.rule_id).statement) << " |\n";
  }
  md << "\n## Timeline\n\n";
  for (const ChannelEvent& e : r.trace.channel) {
    md << "- t = " << format_number(e.time_s, 2) << " s - " << to_string(e.message.type) << " " << to_string(e.kind)
       << " (" << party_name(Party::from_vehicle_id(e.message.from_id)) << " to " << party_name(Party::from_vehicle_id(e.message.to_id)) << ")\n";
  }
  for (const RuleResult& rule : r.rules) {
    if (!rule.holds) {
      md << "- t = " << format_number(*rule.first_violation_time_s, 2) << " s - violation of " << rule.rule_id << " ("
         << party_name(rule.liable_id) << ")\n";
    }
  }
  const std::vector<PlannerClaim> claims = planner_account(r);
  if (!claims.empty()) md << "\n## The planner's own account (not judged)\n\n";
  for (const PlannerClaim& c : claims) {
    md << "- t = " << format_number(c.time_s, 2) << " s: planner reported " << c.mode;
    if (!c.reason.empty()) md << " - " << c.reason;
    if (c.disagrees) md << " **(disagrees: observed, the ego did not hold the right of way then)**";
    md << "\n";
  }
  md << "\n## Judged with\n\n";
  const nlohmann::json judged = judged_with_json(r);
  for (const auto& [group, values] : judged.items())
    for (const auto& [name, value] : values.items()) md << "- `" << group << "." << name << "` = " << value.dump() << "\n";
  md << "\nTrace: " << r.trace.steps.size() << " steps, digest " << std::hex << r.trace_digest << std::dec << ".\n";
  return md.str();
}

}  // namespace mg
