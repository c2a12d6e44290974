#include "api/json_writer.h"

#include <array>
#include <cmath>

#include "api/json_endpoint.h"

namespace cutcalc::api {

// Room for the answers of the hot endpoints without growing.
JsonWriter::JsonWriter() { text_.reserve(256); }

void JsonWriter::before_value() {
  if (!after_key_ && !first_member_) {
    text_ += ',';
  }
  after_key_ = false;
}

void JsonWriter::begin_object() {
  before_value();
  text_ += '{';
  first_member_ = true;
}

void JsonWriter::end_object() {
  text_ += '}';
  first_member_ = false;
}

void JsonWriter::key(std::string_view name) {
  if (!first_member_) {
    text_ += ',';
  }
  first_member_ = false;
  text_ += '"';
  text_ += name;
  text_ += "\":";
  after_key_ = true;
}

void JsonWriter::number(double value) {
  before_value();
  if (!std::isfinite(value)) {
    all_finite_ = false;
    text_ += "null";  // as dump() writes it; the answer is refused for it anyway
    return;
  }
  std::array<char, 64> digits{};  // dump()'s own buffer size
  char* end = nlohmann::detail::to_chars(digits.data(), digits.data() + digits.size(), value);
  text_.append(digits.data(), static_cast<std::size_t>(end - digits.data()));
}

void JsonWriter::word(std::string_view text) {
  before_value();
  text_ += '"';
  text_ += text;
  text_ += '"';
}

void JsonWriter::document(const nlohmann::json& value) {
  before_value();
  all_finite_ = all_finite_ && all_numbers_finite(value);
  text_ += value.dump();
}

JsonText JsonWriter::finish() && { return {std::move(text_), all_finite_}; }

}  // namespace cutcalc::api
