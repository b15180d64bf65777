#include "core/param_docs.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace mg {
namespace {

const ParamInfo& find_param(const ParamSection& s, std::string_view name) {
  for (const ParamInfo& p : s.params)
    if (p.name == name) return p;
  throw std::logic_error("params section " + s.name + ": no parameter '" + std::string(name) + "'");
}

// The widest numeric end a bound allows: a parameter bound is at least as far in as that
// parameter's own end, and excludes it when either excludes.
ParamBound static_bound(const ParamSection& s, const ParamBound& b, bool lower) {
  if (b.param.empty()) return b;
  const ParamInfo& other = find_param(s, b.param);
  ParamBound end = static_bound(s, lower ? other.lo : other.hi, lower);
  end.open = end.open || b.open;
  return end;
}

std::string end_text(const ParamBound& b) {
  return b.param.empty() ? doc_number(b.value) : "`" + std::string(b.param) + "`";
}

// The description the schema shows: the meaning, the unit, and what a range cannot say.
std::string schema_description(const ParamInfo& p) {
  std::string d(p.description);
  if (!p.unit.empty()) d += "; unit: " + std::string(p.unit);
  if (!p.lo.param.empty()) d += std::string("; ") + (p.lo.open ? "above " : "at least ") + std::string(p.lo.param);
  if (!p.hi.param.empty()) d += std::string("; ") + (p.hi.open ? "below " : "at most ") + std::string(p.hi.param);
  if (!p.constraint.empty()) d += "; " + std::string(p.constraint);
  return d;
}

nlohmann::ordered_json number_json(const ParamInfo& p, double x) {
  if (p.type == ParamType::kInteger) return static_cast<long long>(x);
  return x;
}

nlohmann::ordered_json param_schema(const ParamSection& s, const ParamInfo& p) {
  nlohmann::ordered_json j;
  j["type"] = p.type == ParamType::kInteger ? "integer" : "number";
  const ParamBound lo = static_bound(s, p.lo, true);
  const ParamBound hi = static_bound(s, p.hi, false);
  j[lo.open ? "exclusiveMinimum" : "minimum"] = number_json(p, lo.value);
  j[hi.open ? "exclusiveMaximum" : "maximum"] = number_json(p, hi.value);
  j["default"] = number_json(p, p.default_value);
  j["description"] = schema_description(p);
  return j;
}

}  // namespace

std::string doc_number(double x) {
  const bool integral = std::floor(x) == x && std::abs(x) < 1e15;
  if (integral && std::abs(x) < 1e5) return std::to_string(static_cast<long long>(x));
  const double exponent = std::log10(std::abs(x));
  if (integral && std::floor(exponent) == exponent)
    return std::string(x < 0 ? "-" : "") + "1e" + std::to_string(static_cast<int>(exponent));
  std::ostringstream out;
  out.precision(10);
  out << x;
  return out.str();
}

std::string doc_range(const ParamInfo& p) {
  std::string r = std::string(p.lo.open ? "(" : "[") + end_text(p.lo) + ", " + end_text(p.hi) + (p.hi.open ? ")" : "]");
  if (p.type == ParamType::kInteger) r += ", integer";
  if (!p.constraint.empty()) r += "; " + std::string(p.constraint);
  return r;
}

std::string params_markdown_table(const std::vector<ParamSection>& sections) {
  std::string md = "| key | unit | default | valid range | meaning |\n|---|---|---|---|---|\n";
  for (const ParamSection& s : sections) {
    for (const ParamInfo& p : s.params) {
      md += "| `" + s.name + "." + std::string(p.name) + "` | " + (p.unit.empty() ? "—" : std::string(p.unit)) + " | " +
            doc_number(p.default_value) + " | " + doc_range(p) + " | " + std::string(p.description) + " |\n";
    }
  }
  return md;
}

nlohmann::ordered_json params_schema(const std::vector<ParamSection>& sections) {
  nlohmann::ordered_json properties = nlohmann::ordered_json::object();
  for (const ParamSection& s : sections) {
    nlohmann::ordered_json section;
    section["type"] = "object";
    section["additionalProperties"] = false;
    section["description"] = s.description;
    nlohmann::ordered_json params = nlohmann::ordered_json::object();
    for (const ParamInfo& p : s.params) params[std::string(p.name)] = param_schema(s, p);
    section["properties"] = params;
    properties[s.name] = section;
  }
  nlohmann::ordered_json j;
  j["type"] = "object";
  j["additionalProperties"] = false;
  j["properties"] = properties;
  return j;
}

namespace {

// "| `rss.response_time_s` | s | 0.5 | ... |" -> its cells, trimmed.
std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t at = line.find('|');
  while (at != std::string::npos) {
    const std::size_t next = line.find('|', at + 1);
    if (next == std::string::npos) break;
    std::string cell = line.substr(at + 1, next - at - 1);
    cell.erase(0, cell.find_first_not_of(' '));
    cell.erase(cell.find_last_not_of(' ') + 1);
    cells.push_back(cell);
    at = next;
  }
  return cells;
}

// Table rows by their first cell (the header row under its own first cell).
std::vector<std::vector<std::string>> rows_of(const std::string& table) {
  std::vector<std::vector<std::string>> rows;
  std::size_t start = 0;
  while (start < table.size()) {
    const std::size_t end = std::min(table.find('\n', start), table.size());
    const std::string line = table.substr(start, end - start);
    if (line.rfind("|", 0) == 0 && line.rfind("|---", 0) != 0) rows.push_back(cells_of(line));
    start = end + 1;
  }
  return rows;
}

const std::vector<std::string>* find_row(const std::vector<std::vector<std::string>>& rows, const std::string& key) {
  for (const auto& r : rows)
    if (!r.empty() && r[0] == key) return &r;
  return nullptr;
}

std::string shown(const nlohmann::ordered_json* v) { return v == nullptr ? "absent" : v->dump(); }

void compare_fields(const std::string& where, const nlohmann::ordered_json& committed,
                    const nlohmann::ordered_json& generated, std::vector<std::string>& out) {
  std::vector<std::string> fields;
  for (const auto& item : generated.items()) fields.push_back(item.key());
  for (const auto& item : committed.items())
    if (!generated.contains(item.key())) fields.push_back(item.key());
  for (const std::string& f : fields) {
    const nlohmann::ordered_json* c = committed.contains(f) ? &committed.at(f) : nullptr;
    const nlohmann::ordered_json* g = generated.contains(f) ? &generated.at(f) : nullptr;
    if (c == nullptr || g == nullptr || *c != *g)
      out.push_back(where + ": " + f + ": " + shown(c) + " in the file, " + shown(g) + " in the table");
  }
}

// Compares two schema nodes; the next `levels` levels of "properties" key by key.
void compare_node(const std::string& where, const nlohmann::ordered_json& committed,
                  const nlohmann::ordered_json& generated, int levels, std::vector<std::string>& out) {
  if (levels == 0 || !committed.is_object()) {
    compare_fields(where, committed.is_object() ? committed : nlohmann::ordered_json::object(), generated, out);
    return;
  }
  nlohmann::ordered_json c_head = committed;
  nlohmann::ordered_json g_head = generated;
  c_head.erase("properties");
  g_head.erase("properties");
  compare_fields(where, c_head, g_head, out);
  const nlohmann::ordered_json none = nlohmann::ordered_json::object();
  const auto& c_props = committed.contains("properties") ? committed.at("properties") : none;
  const auto& g_props = generated.at("properties");
  for (const auto& item : g_props.items()) {
    if (!c_props.contains(item.key())) out.push_back(where + "." + item.key() + ": missing from the file");
    else compare_node(where + "." + item.key(), c_props.at(item.key()), item.value(), levels - 1, out);
  }
  for (const auto& item : c_props.items())
    if (!g_props.contains(item.key())) out.push_back(where + "." + item.key() + ": in the file, in no parameter table");
}

}  // namespace

std::string marked_block(const std::string& text) {
  const std::size_t begin = text.find(kParamsTableBegin);
  const std::size_t end = text.find(kParamsTableEnd);
  if (begin == std::string::npos || end == std::string::npos || end < begin)
    throw std::invalid_argument("the generated params table's markers are missing");
  const std::size_t from = text.find('\n', begin) + 1;
  return text.substr(from, end - from);
}

std::string replace_marked_block(const std::string& text, const std::string& block) {
  const std::string old = marked_block(text);
  const std::size_t from = text.find('\n', text.find(kParamsTableBegin)) + 1;
  return text.substr(0, from) + block + text.substr(from + old.size());
}

std::vector<std::string> markdown_table_differences(const std::string& committed, const std::string& generated) {
  const auto c_rows = rows_of(committed);
  const auto g_rows = rows_of(generated);
  std::vector<std::string> out;
  const auto& header = g_rows.front();
  for (const auto& g : g_rows) {
    const auto* c = find_row(c_rows, g[0]);
    if (c == nullptr) {
      out.push_back("docs table: no row " + g[0]);
      continue;
    }
    for (std::size_t i = 1; i < g.size(); ++i) {
      const std::string in_file = i < c->size() ? (*c)[i] : "absent";
      if (in_file != g[i])
        out.push_back("docs table: " + g[0] + ": " + header[i] + ": " + in_file + " in the file, " + g[i] + " in the table");
    }
    if (c->size() > g.size()) out.push_back("docs table: " + g[0] + ": more columns than the table's");
  }
  for (const auto& c : c_rows)
    if (!c.empty() && find_row(g_rows, c[0]) == nullptr) out.push_back("docs table: row " + c[0] + " is in no parameter table");
  return out;
}

std::vector<std::string> schema_differences(const nlohmann::ordered_json& committed,
                                            const nlohmann::ordered_json& generated) {
  std::vector<std::string> out;
  compare_node("params", committed, generated, 2, out);
  return out;
}

}  // namespace mg
