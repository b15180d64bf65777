// Numbers in fixed notation for reports and decision reasons: printf's "%.*f" (std::to_chars is
// specified to print the same) without its cost, which showed in the planners' per-cycle reasons.
#pragma once

#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <system_error>

namespace mg {

inline std::string fixed_text(double v, int decimals) {
  char buf[400];  // the largest double in fixed notation has 309 digits before the point
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  if (r.ec != std::errc()) return "?";  // more decimals than any caller asks for
  return std::string(buf, r.ptr);
}

// A report's number: "n/a" where it is missing or not finite.
inline std::string fixed_or_na(double v, int decimals = 2) {
  return std::isfinite(v) ? fixed_text(v, decimals) : "n/a";
}
inline std::string fixed_or_na(const std::optional<double>& v, int decimals = 2) {
  return v ? fixed_or_na(*v, decimals) : "n/a";
}

}  // namespace mg
