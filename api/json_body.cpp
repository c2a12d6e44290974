#include "api/json_body.h"

#include <algorithm>
#include <cctype>
#include <set>
#include <string>
#include <vector>

namespace cutcalc::api {
namespace {

// Thrown from the parser callback to stop parsing early; never escapes this file.
struct Rejected {
  Message why;
};

std::string lower_trimmed(std::string_view text) {
  const auto not_space = [](unsigned char c) { return std::isspace(c) == 0; };
  const auto begin = std::find_if(text.begin(), text.end(), not_space);
  const auto end = std::find_if(text.rbegin(), text.rend(), not_space).base();
  std::string out(begin, begin < end ? end : begin);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

}  // namespace

bool is_json_media_type(std::string_view content_type) {
  const std::string_view media = content_type.substr(0, content_type.find(';'));
  return lower_trimmed(media) == "application/json";
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

}  // namespace

std::variant<nlohmann::json, Problem> parse_json_body(std::string_view body) {
  if (body.empty()) {
    return Problem{ProblemKind::malformed_json, Message{ErrorCode::empty_body}, {}};
  }
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
      return invalid_input({FieldError{position.pointer(), ErrorCode::not_finite, {}}});
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

}  // namespace cutcalc::api
