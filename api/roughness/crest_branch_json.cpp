#include "api/roughness/crest_branch_json.h"

namespace cutcalc::api::roughness {

const char* to_string(domain::roughness::CrestBranch branch) {
  switch (branch) {
    case domain::roughness::CrestBranch::nose_arc:
      return "nose_arc";
    case domain::roughness::CrestBranch::nose_arc_and_minor_edge:
      return "nose_arc_and_minor_edge";
    case domain::roughness::CrestBranch::minor_edge_and_main_edge:
      break;
  }
  return "minor_edge_and_main_edge";
}

}  // namespace cutcalc::api::roughness
