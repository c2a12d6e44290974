#include "api/field_reader.h"

#include <algorithm>
#include <cmath>

namespace cutcalc::api {
namespace {

// RFC 6901: '~' and '/' inside a key are escaped as ~0 and ~1.
std::string escape_pointer_token(std::string_view key) {
  std::string out;
  out.reserve(key.size());
  for (const char c : key) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

// Whole bounds print as integers ("maximum": 12, not 12.0).
nlohmann::json bound_value(double value) {
  if (std::trunc(value) == value && std::fabs(value) < 1.0e15) {
    return static_cast<std::int64_t>(value);
  }
  return value;
}

// The bounds as errors[] parameters: minimum or exclusive_minimum, maximum or exclusive_maximum.
nlohmann::json bound_params(const Bounds& bounds) {
  nlohmann::json params = nlohmann::json::object();
  if (bounds.min) {
    params[bounds.min_inclusive ? "minimum" : "exclusive_minimum"] = bound_value(*bounds.min);
  }
  if (bounds.max) {
    params[bounds.max_inclusive ? "maximum" : "exclusive_maximum"] = bound_value(*bounds.max);
  }
  return params;
}

struct Violation {
  ErrorCode code;
  nlohmann::json params;
};

// A value below 0 where 0 is the limit is "must be > 0" / ">= 0"; every other bound violated names
// the whole interval.
std::optional<Violation> violated_bound(double value, const Bounds& bounds) {
  if (bounds.min) {
    const bool below = bounds.min_inclusive ? value < *bounds.min : value <= *bounds.min;
    if (below) {
      if (*bounds.min == 0.0) {
        return Violation{
            bounds.min_inclusive ? ErrorCode::must_not_be_negative : ErrorCode::must_be_positive,
            bound_params(bounds)};
      }
      return Violation{ErrorCode::out_of_range, bound_params(bounds)};
    }
  }
  if (bounds.smallest_positive && value < *bounds.smallest_positive) {
    return Violation{ErrorCode::below_resolution,
                     {{"minimum", bound_value(*bounds.smallest_positive)}}};
  }
  if (bounds.max) {
    const bool above = bounds.max_inclusive ? value > *bounds.max : value >= *bounds.max;
    if (above) {
      return Violation{ErrorCode::out_of_range, bound_params(bounds)};
    }
  }
  return std::nullopt;
}

}  // namespace

ObjectReader::ObjectReader(const nlohmann::json* value, std::string pointer,
                           std::vector<FieldError>& errors)
    : object_(value != nullptr && value->is_object() ? value : nullptr),
      pointer_(std::move(pointer)),
      errors_(&errors) {}

bool ObjectReader::has(std::string_view key) const {
  return object_ != nullptr && object_->find(key) != object_->end();
}

const nlohmann::json* ObjectReader::find(std::string_view key) {
  if (object_ == nullptr) {
    return nullptr;
  }
  const auto it = object_->find(key);
  if (it == object_->end()) {
    return nullptr;
  }
  asked_.push_back(&*it);
  return &*it;
}

std::string ObjectReader::child_pointer(std::string_view key) const {
  return pointer_ + "/" + escape_pointer_token(key);
}

void ObjectReader::add_error(std::string_view key, ErrorCode code, nlohmann::json params) {
  errors_->push_back({child_pointer(key), code, std::move(params)});
}

void ObjectReader::reject(std::string_view key, ErrorCode code, nlohmann::json params) {
  find(key);  // reported here, so not again as unknown
  add_error(key, code, std::move(params));
}

std::optional<double> ObjectReader::optional_number(std::string_view key, const Bounds& bounds) {
  const nlohmann::json* value = find(key);
  if (value == nullptr) {
    return std::nullopt;
  }
  return check_number(key, *value, bounds);
}

std::optional<double> ObjectReader::check_number(std::string_view key, const nlohmann::json& value,
                                                 const Bounds& bounds) {
  if (!value.is_number()) {
    add_error(key, ErrorCode::not_a_number);
    return std::nullopt;
  }
  const double number = value.get<double>();
  if (!std::isfinite(number)) {
    add_error(key, ErrorCode::not_finite);
    return std::nullopt;
  }
  if (auto violation = violated_bound(number, bounds)) {
    add_error(key, violation->code, std::move(violation->params));
    return std::nullopt;
  }
  return number;
}

std::optional<double> ObjectReader::required_number(std::string_view key, const Bounds& bounds) {
  if (present() && !has(key)) {
    add_error(key, ErrorCode::required);
    return std::nullopt;
  }
  return optional_number(key, bounds);
}

double ObjectReader::number_or(std::string_view key, const Bounds& bounds, double fallback) {
  return optional_number(key, bounds).value_or(fallback);
}

std::optional<std::int64_t> ObjectReader::required_integer(std::string_view key, std::int64_t min,
                                                           std::int64_t max) {
  const auto number = required_number(
      key, Bounds{static_cast<double>(min), true, static_cast<double>(max), true, {}});
  if (!number) {
    return std::nullopt;
  }
  if (std::trunc(*number) != *number) {
    add_error(key, ErrorCode::not_an_integer);
    return std::nullopt;
  }
  return static_cast<std::int64_t>(*number);
}

std::optional<std::vector<double>> ObjectReader::optional_number_list(std::string_view key,
                                                                      const Bounds& bounds,
                                                                      std::size_t min_items,
                                                                      std::size_t max_items) {
  const nlohmann::json* value = find(key);
  if (value == nullptr) {
    return std::nullopt;
  }
  if (!value->is_array() || value->size() < min_items || value->size() > max_items) {
    add_error(key, ErrorCode::wrong_list_length,
              {{"min_items", min_items}, {"max_items", max_items}});
    return std::nullopt;
  }
  ObjectReader elements(nullptr, child_pointer(key), *errors_);
  std::vector<double> numbers;
  numbers.reserve(value->size());
  bool all_valid = true;
  for (std::size_t i = 0; i < value->size(); ++i) {
    const std::string index = std::to_string(i);
    const auto number = elements.check_number(index, (*value)[i], bounds);
    all_valid = all_valid && number.has_value();
    numbers.push_back(number.value_or(0.0));
  }
  return all_valid ? std::optional(std::move(numbers)) : std::nullopt;
}

bool ObjectReader::boolean_or(std::string_view key, bool fallback) {
  const nlohmann::json* value = find(key);
  if (value == nullptr) {
    return fallback;
  }
  if (!value->is_boolean()) {
    add_error(key, ErrorCode::not_a_boolean);
    return fallback;
  }
  return value->get<bool>();
}

namespace {

nlohmann::json list_of(std::initializer_list<std::string_view> allowed) {
  nlohmann::json choices = nlohmann::json::array();
  for (const std::string_view choice : allowed) {
    choices.push_back(choice);
  }
  return choices;
}

}  // namespace

std::optional<std::string> ObjectReader::optional_choice(
    std::string_view key, std::initializer_list<std::string_view> allowed) {
  const nlohmann::json* value = find(key);
  if (value == nullptr) {
    return std::nullopt;
  }
  if (value->is_string()) {
    const auto& text = value->get_ref<const std::string&>();
    for (const std::string_view choice : allowed) {
      if (text == choice) {
        return text;
      }
    }
  }
  add_error(key, ErrorCode::not_one_of, {{"allowed", list_of(allowed)}});
  return std::nullopt;
}

std::optional<std::string_view> ObjectReader::optional_string(std::string_view key) {
  const nlohmann::json* value = find(key);
  if (value == nullptr) {
    return std::nullopt;
  }
  if (!value->is_string()) {
    add_error(key, ErrorCode::not_a_string);
    return std::nullopt;
  }
  return std::string_view(value->get_ref<const std::string&>());
}

std::optional<std::string> ObjectReader::required_choice(
    std::string_view key, std::initializer_list<std::string_view> allowed) {
  if (present() && !has(key)) {
    add_error(key, ErrorCode::required_choice, {{"allowed", list_of(allowed)}});
    return std::nullopt;
  }
  return optional_choice(key, allowed);
}

ObjectReader ObjectReader::object(std::string_view key, bool required) {
  const nlohmann::json* value = find(key);
  if (value == nullptr) {
    if (required && present()) {
      add_error(key, ErrorCode::required);
    }
  } else if (!value->is_object()) {
    add_error(key, ErrorCode::not_an_object);
  }
  return ObjectReader(value, child_pointer(key), *errors_);
}

void ObjectReader::reject_unknown_fields() {
  if (object_ == nullptr) {
    return;
  }
  for (auto member = object_->begin(); member != object_->end(); ++member) {
    if (std::find(asked_.begin(), asked_.end(), &*member) == asked_.end()) {
      add_error(member.key(), ErrorCode::unknown_field);
    }
  }
}

ObjectReader root_reader(const nlohmann::json& body, std::vector<FieldError>& errors) {
  if (!body.is_object()) {
    errors.push_back({"", ErrorCode::body_not_an_object, {}});
  }
  return ObjectReader(&body, "", errors);
}

}  // namespace cutcalc::api
