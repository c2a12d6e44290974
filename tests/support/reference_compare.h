#pragma once
// Compares a response with a reference case's expected subset (shared/reference/*.json rules):
// numbers within a tolerance, strings exactly, lists element-wise with equal length, objects
// recursively, fields absent from the expectation ignored.

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

// Tolerance rule of entry-length.json and main-time.json: abs_min for *_time_min keys and
// main_time_min, abs_mm for every other number.
ToleranceFn entry_file_tolerance(const nlohmann::json& tolerance);

// True when the problem body's errors[] has an entry with exactly this pointer.
bool problem_names_pointer(const nlohmann::json& problem, const std::string& pointer);

}  // namespace cutcalc::testing
