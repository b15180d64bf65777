#include "core/param_table.h"

namespace mg::param_detail {

NumberRange resolve_range(const ParamInfo& p, const std::function<double(std::string_view)>& value_of) {
  NumberRange r;
  r.lo = p.lo.param.empty() ? p.lo.value : value_of(p.lo.param);
  r.lo_open = p.lo.open;
  r.lo_name = std::string(p.lo.param);
  r.hi = p.hi.param.empty() ? p.hi.value : value_of(p.hi.param);
  r.hi_open = p.hi.open;
  r.hi_name = std::string(p.hi.param);
  return r;
}

double read_value(const ObjectReader& r, const ParamInfo& p, const NumberRange& range) {
  // well_formed() holds integers to closed numeric ends.
  if (p.type == ParamType::kInteger)
    return static_cast<double>(r.integer(p.name, static_cast<long long>(range.lo), static_cast<long long>(range.hi)));
  return r.number_in(p.name, range);
}

void unknown_param(std::string_view name) {
  throw std::logic_error("parameter table: no parameter '" + std::string(name) + "'");
}

}  // namespace mg::param_detail
