#include "api/milling_sense_json.h"

namespace cutcalc::api {

std::optional<domain::MillingSense> read_milling(ObjectReader& in) {
  const auto name = in.required_choice("milling", {"up", "down"});
  if (!name) {
    return std::nullopt;
  }
  return *name == "up" ? domain::MillingSense::up : domain::MillingSense::down;
}

const char* to_string(domain::MillingSense sense) {
  return sense == domain::MillingSense::up ? "up" : "down";
}

}  // namespace cutcalc::api
