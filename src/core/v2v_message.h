// V2V messages of Definition 2 (RCPP §II-A): a cooperation request carrying P_c and D*_lon,
// and the responder's acceptance or refusal.
#pragma once

#include <limits>
#include <string>

namespace mg {

enum class MessageType { kRequest, kAccept, kRefuse };

// Which clause of Definition 2 the request invokes.
enum class CoopCase {
  kEgoAhead,   // Def. 2.1: the ego merges ahead of the responder, which brakes to v_o* (ineq. 3)
  kEgoBehind,  // Def. 2.2: the ego merges behind the responder, which accelerates to v_o* (ineq. 4)
};

struct V2vMessage {
  MessageType type = MessageType::kRequest;
  int from_id = 0;              // 0 = ego
  int to_id = 0;
  double sent_time_s = 0.0;
  CoopCase coop_case = CoopCase::kEgoAhead;
  double pc_m = 0.0;            // P_c of the ego's sigmoid (request)
  double d_lon_star_m = 0.0;    // D*_lon: the ego's predicted safe distance at P_c (request)
  double target_speed_mps = 0.0;// v_o* asked of the responder (request)
  // When the channel delivered it (NaN until then): the receiver knows when a message arrived,
  // and Def. 2.3's rho_c window is about that instant, not the planner cycle that reads it.
  double delivered_time_s = std::numeric_limits<double>::quiet_NaN();
  bool operator==(const V2vMessage&) const = default;
};

std::string to_string(MessageType t);
std::string to_string(CoopCase c);

}  // namespace mg
