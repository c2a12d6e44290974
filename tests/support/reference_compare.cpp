#include "support/reference_compare.h"

#include <cmath>
#include <sstream>

namespace cutcalc::testing {
namespace {

void compare_at(const nlohmann::json& expected, const nlohmann::json& actual,
                const std::string& pointer, const std::string& key, const ToleranceFn& tolerance,
                std::vector<std::string>& mismatches) {
  std::ostringstream why;
  if (expected.is_number()) {
    if (!actual.is_number()) {
      why << pointer << ": expected a number " << expected.dump() << ", got " << actual.dump();
    } else {
      const double want = expected.get<double>();
      const double got = actual.get<double>();
      const double allowed = tolerance(key, want);
      if (!(std::abs(got - want) <= allowed)) {
        why.precision(17);
        why << pointer << ": expected " << want << " +- " << allowed << ", got " << got
            << " (off by " << std::abs(got - want) << ")";
      }
    }
  } else if (expected.is_object()) {
    if (!actual.is_object()) {
      why << pointer << ": expected an object, got " << actual.dump();
    } else {
      for (const auto& [name, value] : expected.items()) {
        const auto found = actual.find(name);
        if (found == actual.end()) {
          mismatches.push_back(pointer + "/" + name + ": missing");
        } else {
          compare_at(value, *found, pointer + "/" + name, name, tolerance, mismatches);
        }
      }
    }
  } else if (expected.is_array()) {
    if (!actual.is_array() || actual.size() != expected.size()) {
      why << pointer << ": expected a list of " << expected.size() << ", got " << actual.dump();
    } else {
      for (std::size_t i = 0; i < expected.size(); ++i) {
        compare_at(expected[i], actual[i], pointer + "/" + std::to_string(i), key, tolerance,
                   mismatches);
      }
    }
  } else if (expected != actual) {
    why << pointer << ": expected " << expected.dump() << ", got " << actual.dump();
  }
  if (!why.str().empty()) {
    mismatches.push_back(why.str());
  }
}

}  // namespace

std::vector<std::string> compare_subset(const nlohmann::json& expected,
                                        const nlohmann::json& actual,
                                        const ToleranceFn& tolerance) {
  std::vector<std::string> mismatches;
  compare_at(expected, actual, "", "", tolerance, mismatches);
  return mismatches;
}

bool problem_names_pointer(const nlohmann::json& problem, const std::string& pointer) {
  if (!problem.is_object() || !problem.contains("errors") || !problem["errors"].is_array()) {
    return false;
  }
  for (const auto& error : problem["errors"]) {
    if (error.is_object() && error.value("pointer", std::string("\x01")) == pointer) {
      return true;
    }
  }
  return false;
}

}  // namespace cutcalc::testing
