#pragma once
// A JSON answer written straight to text: no document to build, walk, dump and free (for the
// entry-length answer those cost ~1 us of a 13 us request). Numbers are formatted by
// nlohmann's own formatter, as dump() formats them, so an answer reads the same byte for byte
// whichever way it was made. Members must be written in key order (the order dump() gives).

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace cutcalc::api {

// An answer already in JSON text; all_finite is false when a number was NaN or infinite (the
// text then holds null there, and the answer must not be sent).
struct JsonText {
  std::string text;
  bool all_finite = true;
};

class JsonWriter {
 public:
  JsonWriter();
  void begin_object();
  void end_object();
  // An object member's name: plain ASCII, nothing to escape (the API's field names).
  void key(std::string_view name);
  void number(double value);
  void member(std::string_view name, double value) {
    key(name);
    number(value);
  }
  // A value that is a word of the API (an enum name): nothing to escape.
  void word(std::string_view text);
  // A nested document, as dump() writes it.
  void document(const nlohmann::json& value);
  [[nodiscard]] JsonText finish() &&;

 private:
  void before_value();

  std::string text_;
  bool first_member_ = true;
  bool after_key_ = false;
  bool all_finite_ = true;
};

}  // namespace cutcalc::api
