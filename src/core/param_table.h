// Parameter tables: each parameter structure (RssParams, RuleParams, RCPP's RcppParams, ...) has
// one table, a row per parameter with its JSON key, unit, valid range and a one-line description;
// its default is the structure's member initialiser. Reading (with the error messages),
// writing, validation and the generated documentation (core/param_docs.h: the table of
// docs/scenario_format.md, the schema fragments of docs/*.schema.json) all come from the table,
// so that each of these facts is written once.
#pragma once

#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/json_reader.h"

namespace mg {

enum class ParamType { kNumber, kInteger };

// One end of a parameter's valid range: a number, or the value of another parameter of the same
// table (a cross-parameter bound such as kappa_min_per_m <= kappa_max_per_m), which must come
// earlier in the table so that it is read first.
struct ParamBound {
  double value = 0.0;
  bool open = false;       // the end itself is outside the range
  std::string_view param;  // non-empty: the end is this parameter's value
};
constexpr ParamBound at_least(double v) { return {v, false, {}}; }
constexpr ParamBound above(double v) { return {v, true, {}}; }
constexpr ParamBound at_most(double v) { return {v, false, {}}; }
constexpr ParamBound below(double v) { return {v, true, {}}; }
constexpr ParamBound at_least_param(std::string_view name) { return {0.0, false, name}; }
constexpr ParamBound below_param(std::string_view name) { return {0.0, true, name}; }

// A parameter as the documentation sees it, whatever structure it belongs to.
struct ParamInfo {
  std::string_view name;
  std::string_view unit;  // "s", "m", "m/s", "m/s²", "1/m", "rad", "" (a count or a pure number)
  ParamType type = ParamType::kNumber;
  ParamBound lo;
  ParamBound hi;
  std::string_view description;
  double default_value = 0.0;
  std::string_view constraint;  // a further condition a range cannot state (ParamCheck::rule)
};

// A JSON object of parameters as the documentation sees it: params.rss, params.rules, ...
struct ParamSection {
  std::string name;         // the key in the params object
  std::string description;  // one line
  std::vector<ParamInfo> params;
};

// One row: exactly one of `number` and `integer` is set (param() below).
template <class Owner>
struct Param {
  std::string_view name;
  std::string_view unit;
  double Owner::*number = nullptr;
  int Owner::*integer = nullptr;
  ParamBound lo;
  ParamBound hi;
  std::string_view description;

  constexpr ParamType type() const { return number != nullptr ? ParamType::kNumber : ParamType::kInteger; }
  constexpr double get(const Owner& o) const { return number != nullptr ? o.*number : static_cast<double>(o.*integer); }
};

template <class Owner>
constexpr Param<Owner> param(std::string_view name, double Owner::*member, std::string_view unit, ParamBound lo,
                             ParamBound hi, std::string_view description) {
  return {name, unit, member, nullptr, lo, hi, description};
}
template <class Owner>
constexpr Param<Owner> param(std::string_view name, int Owner::*member, std::string_view unit, ParamBound lo,
                             ParamBound hi, std::string_view description) {
  return {name, unit, nullptr, member, lo, hi, description};
}

// A condition between parameters that no range states (horizon_s / step_s <= 1e6), checked once
// every key is read; a failure names `param`.
template <class Owner>
struct ParamCheck {
  std::string_view param;
  std::string_view rule;   // as the documentation states it
  std::string_view error;  // the message of a failure
  bool (*holds)(const Owner&) = nullptr;
};

template <class Owner>
struct ParamTable {
  std::span<const Param<Owner>> params;
  std::span<const ParamCheck<Owner>> checks = {};
};

// Whether a table can be read in order: unique names; a parameter bound names a parameter of
// the same type declared before; numeric ends in order; integers with closed numeric ends.
// Tables are constexpr, so each owner static_asserts this of its own.
template <class Owner>
constexpr bool well_formed(std::span<const Param<Owner>> rows) {
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Param<Owner>& p = rows[i];
    if ((p.number == nullptr) == (p.integer == nullptr) || p.name.empty() || p.description.empty()) return false;
    for (std::size_t j = 0; j < i; ++j)
      if (rows[j].name == p.name) return false;
    for (const ParamBound& b : {p.lo, p.hi}) {
      if (b.param.empty()) continue;
      bool earlier = false;
      for (std::size_t j = 0; j < i; ++j) earlier = earlier || (rows[j].name == b.param && rows[j].type() == p.type());
      if (!earlier) return false;
    }
    if (p.lo.param.empty() && p.hi.param.empty() && !(p.lo.value < p.hi.value)) return false;
    if (p.integer != nullptr && (p.lo.open || p.hi.open || !p.lo.param.empty() || !p.hi.param.empty() ||
                                 p.lo.value != static_cast<long long>(p.lo.value) ||
                                 p.hi.value != static_cast<long long>(p.hi.value)))
      return false;
  }
  return true;
}

namespace param_detail {

// The range of `p` with its parameter ends resolved; `value_of` gives an earlier parameter's value.
NumberRange resolve_range(const ParamInfo& p, const std::function<double(std::string_view)>& value_of);
// One key of `r` by its row (present: the caller checked), in its resolved range.
double read_value(const ObjectReader& r, const ParamInfo& p, const NumberRange& range);
[[noreturn]] void unknown_param(std::string_view name);

template <class Owner>
ParamInfo info_of(const ParamTable<Owner>& t, const Param<Owner>& p) {
  static const Owner defaults{};
  ParamInfo i{p.name, p.unit, p.type(), p.lo, p.hi, p.description, p.get(defaults), {}};
  for (const ParamCheck<Owner>& c : t.checks)
    if (c.param == p.name) i.constraint = c.rule;
  return i;
}

template <class Owner>
double value_of(const ParamTable<Owner>& t, const Owner& o, std::string_view name) {
  for (const Param<Owner>& p : t.params)
    if (p.name == name) return p.get(o);
  unknown_param(name);
}

}  // namespace param_detail

// The rows as the documentation sees them, in table order.
template <class Owner>
std::vector<ParamInfo> param_infos(const ParamTable<Owner>& t) {
  std::vector<ParamInfo> out;
  for (const Param<Owner>& p : t.params) out.push_back(param_detail::info_of(t, p));
  return out;
}

// Whether the table declares `key` (the others are unknown, or another owner's).
template <class Owner>
bool declares(const ParamTable<Owner>& t, std::string_view key) {
  for (const Param<Owner>& p : t.params)
    if (p.name == key) return true;
  return false;
}

// Reads the keys of `r` that the table declares into `out` (absent keys keep out's values), in
// table order, then the table's checks. Unknown keys are the caller's: read_params rejects them.
// Errors are InputError naming the source and the key's JSON path.
template <class Owner>
void read_param_values(const ParamTable<Owner>& t, const ObjectReader& r, Owner& out) {
  for (const Param<Owner>& p : t.params) {
    if (!r.has(p.name)) continue;
    const ParamInfo info = param_detail::info_of(t, p);
    const NumberRange range =
        param_detail::resolve_range(info, [&](std::string_view n) { return param_detail::value_of(t, out, n); });
    const double x = param_detail::read_value(r, info, range);
    if (p.number != nullptr) out.*p.number = x;
    else out.*p.integer = static_cast<int>(x);
  }
  for (const ParamCheck<Owner>& c : t.checks)
    if (!c.holds(out)) r.fail(c.param, std::string(c.error));
}

// The whole object: every key optional (the structure's defaults), unknown keys rejected.
template <class Owner>
Owner read_params(const ParamTable<Owner>& t, const ObjectReader& r) {
  for (const auto& item : r.value().items())
    if (!declares(t, item.key())) r.fail(item.key(), "unknown key");
  Owner out{};
  read_param_values(t, r, out);
  return out;
}

// Every parameter of `o` (integers as JSON integers).
template <class Owner>
nlohmann::json params_to_json(const ParamTable<Owner>& t, const Owner& o) {
  nlohmann::json j = nlohmann::json::object();
  for (const Param<Owner>& p : t.params) {
    if (p.number != nullptr) j[std::string(p.name)] = o.*p.number;
    else j[std::string(p.name)] = o.*p.integer;
  }
  return j;
}

}  // namespace mg
