#include "core/v2v_message.h"

namespace mg {

std::string to_string(MessageType t) {
  switch (t) {
    case MessageType::kRequest: return "request";
    case MessageType::kAccept: return "accept";
    case MessageType::kRefuse: return "refuse";
  }
  return "unknown";
}

std::string to_string(CoopCase c) {
  return c == CoopCase::kEgoAhead ? "ego_ahead" : "ego_behind";
}

}  // namespace mg
