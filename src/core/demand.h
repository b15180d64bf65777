// MG_DEMAND(condition): an invariant check that stays on in every build, Release included (as
// Drake's DRAKE_DEMAND). A false condition is a bug of mergeguard, not bad input (input is
// validated once, at the boundary, with an InputError): it prints the condition and where it
// failed on stderr and aborts, so that a campaign, a test or the coverage-guided fuzzer stops at
// the broken invariant instead of judging what follows from it. Use it instead of MG_DEMAND(),
// which NDEBUG compiles out of the builds that CI and fuzzing run.
#pragma once

namespace mg::detail {

[[noreturn]] void demand_failed(const char* condition, const char* file, int line) noexcept;

}  // namespace mg::detail

#define MG_DEMAND(condition)                                                        \
  do {                                                                              \
    if (!(condition)) [[unlikely]]                                                  \
      ::mg::detail::demand_failed(#condition, __FILE__, __LINE__);                  \
  } while (false)
