#pragma once
// Compares a response with an expected subset: numbers within a tolerance, strings exactly, lists
// element-wise with equal length, objects recursively, fields absent from the expectation ignored.

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace cutcalc::testing {

// The allowed |got - want| for a number at `key` (the last object key on its path).
using ToleranceFn = std::function<double(const std::string& key, double want)>;

// Every mismatch as "pointer: why"; empty when `actual` matches `expected`.
std::vector<std::string> compare_subset(const nlohmann::json& expected,
                                        const nlohmann::json& actual, const ToleranceFn& tolerance);

// True when the problem body's errors[] has an entry with exactly this pointer.
bool problem_names_pointer(const nlohmann::json& problem, const std::string& pointer);

}  // namespace cutcalc::testing
