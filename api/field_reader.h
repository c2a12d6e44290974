#pragma once
// Reads the fields of one JSON object into typed values, collecting every field error with its
// JSON Pointer instead of stopping at the first. Each field's own rules (type, finiteness, range)
// live here and only here; rules that relate several fields belong to the domain.

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "api/problem.h"

namespace cutcalc::api {

// The largest size any length field accepts: 1 km is far beyond any machine tool, and the bound
// keeps squares and products of lengths finite in doubles.
inline constexpr double kMaxLengthMm = 1.0e6;

// The smallest positive size, speed or feed accepted: a nanometre is below any machine's
// resolution, and tiny positive products would underflow to 0 and divide.
inline constexpr double kSmallestPositive = 1.0e-6;

// The most teeth a cutter may have: far beyond any real cutter, small enough for every product.
inline constexpr std::int64_t kMaxTeeth = 1000;

struct Bounds {
  std::optional<double> min;
  bool min_inclusive = true;
  std::optional<double> max;
  bool max_inclusive = true;
  std::optional<double> smallest_positive;  // values in (0, this) are refused too

  static Bounds positive(double max = kMaxLengthMm) {
    return {0.0, false, max, true, kSmallestPositive};
  }
  static Bounds non_negative(double max = kMaxLengthMm) { return {0.0, true, max, true, {}}; }
  static Bounds magnitude(double max_abs = kMaxLengthMm) {
    return {-max_abs, true, max_abs, true, {}};
  }
  static Bounds open(double low, double high) { return {low, false, high, false, {}}; }
  static Bounds left_open(double low, double high) { return {low, false, high, true, {}}; }
};

class ObjectReader {
 public:
  // Reads `value` (may be null: absent) found at `pointer`; errors are appended to `errors`.
  ObjectReader(const nlohmann::json* value, std::string pointer, std::vector<FieldError>& errors);

  // The object exists (an absent object reads as empty and reports nothing by itself).
  [[nodiscard]] bool present() const { return object_ != nullptr; }
  [[nodiscard]] bool has(std::string_view key) const;
  [[nodiscard]] const std::string& pointer() const { return pointer_; }

  // Absent: nullopt, no error. Present but not a finite number in bounds: error, nullopt.
  std::optional<double> optional_number(std::string_view key, const Bounds& bounds);
  // Absent: "is required".
  std::optional<double> required_number(std::string_view key, const Bounds& bounds);
  double number_or(std::string_view key, const Bounds& bounds, double fallback);

  // A whole number (2.0 is accepted, 2.5 is not).
  std::optional<std::int64_t> required_integer(std::string_view key, std::int64_t min,
                                               std::int64_t max);

  // Absent: nullopt, no error. Otherwise a list of min_items..max_items finite numbers; each bad
  // element is reported at its own index.
  std::optional<std::vector<double>> optional_number_list(std::string_view key,
                                                          const Bounds& bounds,
                                                          std::size_t min_items,
                                                          std::size_t max_items);

  // Absent: `fallback`, no error. Present: must be true or false (JSON boolean, no 0/1 or
  // "true"); otherwise an error and `fallback`.
  bool boolean_or(std::string_view key, bool fallback);

  // Absent: nullopt, no error. Present: a string that must be one of `allowed`.
  std::optional<std::string> optional_choice(std::string_view key,
                                             std::initializer_list<std::string_view> allowed);
  // Absent: nullopt, no error. Present: must be a JSON string, viewed where the document holds it
  // (a program of many megabytes is not copied).
  std::optional<std::string_view> optional_string(std::string_view key);
  // A string that must be one of `allowed`.
  std::optional<std::string> required_choice(std::string_view key,
                                             std::initializer_list<std::string_view> allowed);

  // A nested object; absent and required: "is required"; not an object: error. Either way the
  // returned reader is usable (it reads as absent).
  ObjectReader object(std::string_view key, bool required);

  // Reports every key that was never asked for as "is not a known field". Call once, last.
  void reject_unknown_fields();

  // Reports a present field that must not be there in this request, with the reason.
  void reject(std::string_view key, ErrorCode code,
              nlohmann::json params = nlohmann::json::object());
  void add_error(std::string_view key, ErrorCode code,
                 nlohmann::json params = nlohmann::json::object());

 private:
  const nlohmann::json* find(std::string_view key);
  // `value` found at `key` must be a finite number within bounds; else an error at `key`.
  std::optional<double> check_number(std::string_view key, const nlohmann::json& value,
                                     const Bounds& bounds);
  std::string child_pointer(std::string_view key) const;

  const nlohmann::json* object_ = nullptr;
  std::string pointer_;
  std::vector<FieldError>* errors_;
  // The members asked for (a few per object: a linear search beats a set of key copies).
  std::vector<const nlohmann::json*> asked_;
};

// Reads the request root: it must be a JSON object (pointer "").
ObjectReader root_reader(const nlohmann::json& body, std::vector<FieldError>& errors);

}  // namespace cutcalc::api
