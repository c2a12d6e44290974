#include "api/json_body.h"

#include <algorithm>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "api/json_number_overflow.h"
#include "domain/common/ascii_text.h"

namespace cutcalc::api {
namespace {

// Thrown from the parser callback to stop parsing early; never escapes this file.
struct Rejected {
  Message why;
};

}  // namespace

bool is_json_media_type(std::string_view content_type) {
  return domain::iequals_ascii(domain::trim_space(content_type.substr(0, content_type.find(';'))),
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

// String values of a body at least this long are decoded here, not by nlohmann's lexer, whose
// token buffer grows by doubling beside a second copy kept for error messages: a 32 MiB program
// to time took 128 MiB to parse, 32 MiB this way.
constexpr std::size_t kLongStringBytes = 64 * 1024;

// A body with its long string values taken out: `skeleton` has "" in their place; they are the
// `ordinals`-th string values in document order (keys not counted), decoded in `values`.
struct LongStrings {
  std::string skeleton;
  std::vector<std::size_t> ordinals;
  std::vector<std::string> values;
};

// A string token's content decoded when it holds only printable ASCII and the two-character
// escapes (what a program is made of); anything else (\u, a control character, a byte above
// 0x7f) is left to nlohmann, which decides what it means and whether it is valid.
std::optional<std::string> decode_plain_string(std::string_view content) {
  std::string text;
  text.reserve(content.size());
  for (std::size_t i = 0; i < content.size(); ++i) {
    const auto byte = static_cast<unsigned char>(content[i]);
    if (byte < 0x20 || byte > 0x7e) return std::nullopt;
    if (content[i] != '\\') {
      text.push_back(content[i]);
      continue;
    }
    if (++i == content.size()) return std::nullopt;
    switch (content[i]) {
      case '"':
      case '\\':
      case '/':
        text.push_back(content[i]);
        break;
      case 'b':
        text.push_back('\b');
        break;
      case 'f':
        text.push_back('\f');
        break;
      case 'n':
        text.push_back('\n');
        break;
      case 'r':
        text.push_back('\r');
        break;
      case 't':
        text.push_back('\t');
        break;
      default:
        return std::nullopt;
    }
  }
  return text;
}

// The body's long string values taken out, or nullopt when it has none this path takes (the body
// is then parsed as it is). Strings are found as JSON lexes them: outside a string, '"' opens
// one; inside, '\\' escapes the next byte and '"' closes it; one followed by ':' is a key. Where
// the body is not valid JSON the skeleton is invalid at the same place, and the parse of the
// body as it is explains why.
std::optional<LongStrings> take_long_strings(std::string_view body) {
  LongStrings taken;
  std::size_t copied = 0;  // body[0, copied) is in the skeleton
  std::size_t value_ordinal = 0;
  for (std::size_t open = body.find('"'); open != std::string_view::npos;) {
    std::size_t close = open + 1;
    while (close < body.size() && body[close] != '"') close += body[close] == '\\' ? 2 : 1;
    if (close >= body.size()) return std::nullopt;  // unterminated
    const std::size_t after = body.find_first_not_of(" \t\n\r", close + 1);
    const bool is_key = after != std::string_view::npos && body[after] == ':';
    if (!is_key) {
      const std::string_view content = body.substr(open + 1, close - open - 1);
      if (content.size() >= kLongStringBytes) {
        auto text = decode_plain_string(content);
        if (!text) return std::nullopt;
        taken.skeleton.append(body.substr(copied, open + 1 - copied));
        copied = close;
        taken.ordinals.push_back(value_ordinal);
        taken.values.push_back(std::move(*text));
      }
      ++value_ordinal;
    }
    open = body.find('"', close + 1);
  }
  if (taken.values.empty()) return std::nullopt;
  taken.skeleton.append(body.substr(copied));
  return taken;
}

// The common case without the bookkeeping (the strict parse below cost ~1.3 us of a
// 15 us request): builds the document as nlohmann's own DOM parser does and counts each object's
// keys. It gives up (false) at the first thing the strict parse must explain, which then runs on
// the same bytes: a syntax error, a number beyond a double, nesting at the limit, or a repeated
// key (an object ends with fewer members than keys read).
class PlainDocumentBuilder {
 public:
  using json = nlohmann::json;
  // `long_strings`: the values take_long_strings took out of the text being parsed.
  explicit PlainDocumentBuilder(json& root, LongStrings* long_strings = nullptr)
      : root_(root), long_strings_(long_strings) {}

  bool null() { return put(nullptr); }
  bool boolean(bool value) { return put(value); }
  bool number_integer(json::number_integer_t value) { return put(value); }
  bool number_unsigned(json::number_unsigned_t value) { return put(value); }
  bool number_float(json::number_float_t value, const json::string_t& /*text*/) {
    return put(value);
  }
  bool string(json::string_t& value) {
    const std::size_t ordinal = string_values_++;
    if (long_strings_ != nullptr && next_long_ < long_strings_->ordinals.size() &&
        long_strings_->ordinals[next_long_] == ordinal) {
      return put(std::move(long_strings_->values[next_long_++]));
    }
    return put(std::move(value));
  }
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
  LongStrings* long_strings_;
  std::size_t string_values_ = 0;  // string values seen (keys not counted)
  std::size_t next_long_ = 0;      // the next of long_strings_ to put in place
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
  if (body.size() >= kLongStringBytes) {
    if (auto taken = take_long_strings(body)) {
      nlohmann::json document;
      PlainDocumentBuilder builder(document, &*taken);
      if (nlohmann::json::sax_parse(taken->skeleton.begin(), taken->skeleton.end(), &builder)) {
        return document;
      }
    }
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
