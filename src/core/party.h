// Who a duty or the right of way belongs to: nobody, the ego, the main-lane traffic as a whole,
// or one main-lane vehicle. A type of its own rather than an int, so that a party is never
// mistaken for a vehicle index or a trace's vehicle id, and so that the sentinels cannot be
// compared with arbitrary numbers.
#pragma once

#include <compare>
#include <optional>
#include <iosfwd>
#include <string>

#include "core/demand.h"

namespace mg {

class Party {
 public:
  static constexpr Party nobody() { return Party(kNobodyCode); }
  static constexpr Party ego() { return Party(kEgoCode); }
  static constexpr Party main_lane() { return Party(kMainLaneCode); }
  // A main-lane vehicle by its trace id (>= 1).
  static Party vehicle(int id) {
    MG_DEMAND(id >= 1);
    return Party(id);
  }
  // The party of a trace's vehicle id: 0 is the ego, >= 1 a main-lane vehicle (ids are
  // validated when a trace is read, so a negative one here is a bug).
  static Party from_vehicle_id(int id) {
    MG_DEMAND(id >= 0);
    return Party(id);
  }

  constexpr bool is_nobody() const { return code_ == kNobodyCode; }
  constexpr bool is_ego() const { return code_ == kEgoCode; }
  constexpr bool is_main_lane() const { return code_ == kMainLaneCode; }
  constexpr bool is_vehicle() const { return code_ >= 1; }
  int vehicle_id() const {
    MG_DEMAND(is_vehicle());
    return code_;
  }

  // The number the JSON outputs write (-1 nobody, 0 ego, -2 main lane, else the vehicle id):
  // kept so that reports, corpus cases and summaries stay readable by earlier tools.
  constexpr int code() const { return code_; }
  // The party a serialized number names, or nullopt when it names none: readers turn that
  // into an InputError at the boundary.
  static constexpr std::optional<Party> from_code(int code) {
    if (code == kNobodyCode || code == kEgoCode || code == kMainLaneCode || code >= 1) return Party(code);
    return std::nullopt;
  }

  friend constexpr auto operator<=>(const Party&, const Party&) = default;

 private:
  static constexpr int kNobodyCode = -1;
  static constexpr int kEgoCode = 0;
  static constexpr int kMainLaneCode = -2;
  explicit constexpr Party(int code) : code_(code) {}
  int code_;
};

// "none", "ego", "main lane" or "vehicle 3": the wording of every report.
std::string party_name(Party party);

// GoogleTest prints a failed expectation's Party by its name rather than its bytes.
void PrintTo(Party party, std::ostream* os);

}  // namespace mg
