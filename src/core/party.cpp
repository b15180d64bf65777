#include "core/party.h"

#include <ostream>

namespace mg {

std::string party_name(Party party) {
  if (party.is_nobody()) return "none";
  if (party.is_ego()) return "ego";
  if (party.is_main_lane()) return "main lane";
  return "vehicle " + std::to_string(party.vehicle_id());
}

void PrintTo(Party party, std::ostream* os) { *os << party_name(party); }

}  // namespace mg
