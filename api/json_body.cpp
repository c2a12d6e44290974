#include "api/json_body.h"

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "api/header_text.h"
#include "api/json_number_overflow.h"

namespace cutcalc::api {
namespace {

// Thrown from the parser callback to stop parsing early; never escapes this file.
struct Rejected {
  Message why;
};

}  // namespace

bool is_json_media_type(std::string_view content_type) {
  return iequals_ascii(trim_space(content_type.substr(0, content_type.find(';'))),
                       "application/json");
}

namespace {

// Where the parser is, as a JSON Pointer: an overflowing number is a field error (422 at its
// field), not malformed JSON, so its position must be known when the parser gives up.
class PositionTracker {
 public:
  void object_start() { frames_.push_back({false, {}, 0}); }
  void array_start() { frames_.push_back({true, {}, 0}); }
  void key(const std::string& name) { frames_.back().key = name; }
  void value_done() {
    if (!frames_.empty() && frames_.back().is_array) {
      ++frames_.back().index;
    }
  }
  void container_end() {
    frames_.pop_back();
    value_done();
  }
  [[nodiscard]] std::string pointer() const {
    std::string out;
    for (const Frame& frame : frames_) {
      out += '/';
      if (frame.is_array) {
        out += std::to_string(frame.index);
      } else {
        for (const char c : frame.key) {
          out += c == '~' ? std::string("~0") : c == '/' ? std::string("~1") : std::string(1, c);
        }
      }
    }
    return out;
  }

 private:
  struct Frame {
    bool is_array;
    std::string key;
    std::size_t index;
  };
  std::vector<Frame> frames_;
};

constexpr int kNumberOverflowId = 406;  // nlohmann::json out_of_range: a number beyond a double

// The common case without the bookkeeping (the strict parse below cost ~1.3 us of a
// 15 us request): builds the document as nlohmann's own DOM parser does and counts each object's
// keys. It gives up (false) at the first thing the strict parse must explain, which then runs on
// the same bytes: a syntax error, a number beyond a double, nesting at the limit, or a repeated
// key (an object ends with fewer members than keys read).
class PlainDocumentBuilder {
 public:
  using json = nlohmann::json;
  explicit PlainDocumentBuilder(json& root) : root_(root) {}

  bool null() { return put(nullptr); }
  bool boolean(bool value) { return put(value); }
  bool number_integer(json::number_integer_t value) { return put(value); }
  bool number_unsigned(json::number_unsigned_t value) { return put(value); }
  bool number_float(json::number_float_t value, const json::string_t& /*text*/) {
    return put(value);
  }
  bool string(json::string_t& value) { return put(std::move(value)); }
  bool binary(json::binary_t& /*value*/) { return false; }  // JSON text has none
  bool start_object(std::size_t /*elements*/) { return open(json::value_t::object); }
  bool key(json::string_t& name) {
    Frame& frame = open_.back();
    ++frame.keys;
    member_ = &(*frame.container)[std::move(name)];
    return true;
  }
  bool end_object() {
    const Frame frame = open_.back();
    open_.pop_back();
    return frame.container->size() == frame.keys;
  }
  bool start_array(std::size_t /*elements*/) { return open(json::value_t::array); }
  bool end_array() {
    open_.pop_back();
    return true;
  }
  bool parse_error(std::size_t /*position*/, const std::string& /*token*/,
                   const json::exception& /*error*/) {
    return false;
  }

 private:
  struct Frame {
    json* container;  // stays valid: only the innermost open container grows
    std::size_t keys;
  };

  // Where the next value goes: the root, the member the last key named, or the array's end.
  json& slot() {
    if (open_.empty()) {
      return root_;
    }
    json& parent = *open_.back().container;
    if (parent.is_array()) {
      return parent.emplace_back();
    }
    return *member_;
  }
  template <class Value>
  bool put(Value&& value) {
    slot() = std::forward<Value>(value);
    return true;
  }
  bool open(json::value_t kind) {
    if (open_.size() >= static_cast<std::size_t>(kMaxJsonDepth)) {
      return false;
    }
    json& container = slot();
    container = json(kind);
    open_.push_back({&container, 0});
    return true;
  }

  json& root_;
  std::vector<Frame> open_;
  json* member_ = nullptr;
};

// A number beyond a double, where the strict parse stopped.
struct Overflow {
  std::string pointer;
};

// The strict parse: every key of every open object remembered and the position tracked, so that
// a rejection can say which key repeated or which field overflowed.
std::variant<nlohmann::json, Problem, Overflow> parse_strictly(std::string_view body);

// A body with numbers beyond a double: parsed with each such number as NaN, so that every field's
// error is listed (api/json_number_overflow.h). A syntax error, a repeated key or deep nesting
// elsewhere is still malformed JSON, reported where the original text has it.
std::variant<nlohmann::json, Problem> parse_with_overflows(std::string_view body,
                                                           const Overflow& first);

}  // namespace

std::variant<nlohmann::json, Problem> parse_json_body(std::string_view body) {
  if (body.empty()) {
    return Problem{ProblemKind::malformed_json, Message{ErrorCode::empty_body}, {}};
  }
  nlohmann::json document;
  PlainDocumentBuilder builder(document);
  if (nlohmann::json::sax_parse(body.begin(), body.end(), &builder)) {
    return document;
  }
  auto strict = parse_strictly(body);
  if (auto* overflow = std::get_if<Overflow>(&strict)) {
    return parse_with_overflows(body, *overflow);
  }
  if (auto* problem = std::get_if<Problem>(&strict)) {
    return std::move(*problem);
  }
  return std::get<nlohmann::json>(std::move(strict));
}

namespace {

std::variant<nlohmann::json, Problem, Overflow> parse_strictly(std::string_view body) {
  // Keys seen so far in each open object, innermost last: duplicate keys are ambiguous input.
  std::vector<std::set<std::string>> open_objects;
  PositionTracker position;
  const nlohmann::json::parser_callback_t guard =
      [&open_objects, &position](int depth, nlohmann::json::parse_event_t event,
                                 nlohmann::json& parsed) {
        using Event = nlohmann::json::parse_event_t;
        if (depth > kMaxJsonDepth) {
          throw Rejected{Message{ErrorCode::too_deeply_nested, {{"levels", kMaxJsonDepth}}}};
        }
        switch (event) {
          case Event::object_start:
            open_objects.emplace_back();
            position.object_start();
            break;
          case Event::array_start:
            position.array_start();
            break;
          case Event::object_end:
            open_objects.pop_back();
            position.container_end();
            break;
          case Event::array_end:
            position.container_end();
            break;
          case Event::key: {
            const auto& key = parsed.get_ref<const std::string&>();
            if (!open_objects.back().insert(key).second) {
              throw Rejected{Message{ErrorCode::duplicate_key, {{"key", key}}}};
            }
            position.key(key);
            break;
          }
          case Event::value:
            position.value_done();
            break;
        }
        return true;
      };
  try {
    return nlohmann::json::parse(body.begin(), body.end(), guard);
  } catch (const Rejected& rejected) {
    return Problem{ProblemKind::malformed_json, rejected.why, {}};
  } catch (const nlohmann::json::out_of_range& error) {
    if (error.id == kNumberOverflowId) {
      return Overflow{position.pointer()};
    }
    return Problem{ProblemKind::malformed_json,
                   Message{ErrorCode::invalid_json, {{"reason", "out of range"}}},
                   {}};
  } catch (const nlohmann::json::exception& error) {
    // The library's message says where parsing stopped; drop its "[json.exception...]" prefix.
    std::string why = error.what();
    if (const auto at = why.find("] "); at != std::string::npos) {
      why = why.substr(at + 2);
    }
    return Problem{
        ProblemKind::malformed_json, Message{ErrorCode::invalid_json, {{"reason", why}}}, {}};
  }
}

std::variant<nlohmann::json, Problem> parse_with_overflows(std::string_view body,
                                                           const Overflow& first) {
  // Should the rewrite miss a number the library overflows on, the first one is said alone.
  const Problem first_alone = invalid_input({FieldError{first.pointer, ErrorCode::not_finite, {}}});
  const OverflowRewrite rewrite = rewrite_overflowing_numbers(body);
  if (rewrite.numbers == 0) {
    return first_alone;
  }
  auto checked = parse_strictly(rewrite.padded);
  if (auto* problem = std::get_if<Problem>(&checked)) {
    return std::move(*problem);
  }
  if (std::holds_alternative<Overflow>(checked)) {
    return first_alone;
  }
  auto marked = parse_strictly(rewrite.marked);
  if (auto* document = std::get_if<nlohmann::json>(&marked)) {
    replace_overflow_markers(*document);
    return std::move(*document);
  }
  return first_alone;
}

}  // namespace

}  // namespace cutcalc::api
