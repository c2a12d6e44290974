#include "api/streamed_json.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "api/json_endpoint.h"

namespace cutcalc::api {
namespace {

// JSON string escaping (RFC 8259 section 7) of a piece of text, appended to `out`.
void append_escaped(std::string& out, std::string_view text) {
  static constexpr char kHex[] = "0123456789abcdef";
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    switch (c) {
      case '"':
        out.append("\\\"");
        break;
      case '\\':
        out.append("\\\\");
        break;
      case '\n':
        out.append("\\n");
        break;
      case '\r':
        out.append("\\r");
        break;
      case '\t':
        out.append("\\t");
        break;
      default:
        if (byte < 0x20) {
          out.append("\\u00").push_back(kHex[byte >> 4]);
          out.push_back(kHex[byte & 0xf]);
        } else {
          out.push_back(c);
        }
    }
  }
}

class StreamedJsonString final : public domain::TextSource {
 public:
  StreamedJsonString(std::string_view key, std::unique_ptr<domain::TextSource> value,
                     const nlohmann::json& rest, std::function<void(nlohmann::json&)> after)
      : value_(std::move(value)), after_(std::move(after)) {
    prefix_ = nlohmann::json(std::string(key)).dump() + ":\"";
    prefix_.insert(prefix_.begin(), '{');
    const std::string members = rest.dump();  // "{...}": the other members, or "{}"
    suffix_ = members.size() > 2 ? "\"," + members.substr(1, members.size() - 2) : "\"";
  }

  bool write_next(std::string& out, std::size_t max_bytes) override {
    if (!prefix_.empty()) {
      out.append(prefix_);
      std::string().swap(prefix_);
    }
    if (value_) {
      piece_.clear();
      const bool more = value_->write_next(piece_, max_bytes);
      append_escaped(out, piece_);
      if (more) return true;
      value_.reset();
      std::string().swap(piece_);
    }
    out.append(suffix_);
    std::string().swap(suffix_);
    if (after_) {
      nlohmann::json members = nlohmann::json::object();
      after_(members);
      after_ = nullptr;
      if (!all_numbers_finite(members))
        throw std::logic_error("a non-finite number after a program");
      for (const auto& [name, member] : members.items()) {
        out.append(",").append(nlohmann::json(name).dump()).append(":").append(member.dump());
      }
    }
    out.push_back('}');
    return false;
  }

  [[nodiscard]] std::size_t held_bytes() const override {
    return sizeof(*this) + prefix_.capacity() + suffix_.capacity() + piece_.capacity() +
           (value_ ? value_->held_bytes() : 0);
  }

 private:
  std::string prefix_;
  std::unique_ptr<domain::TextSource> value_;
  std::string piece_;   // one piece of the value before escaping
  std::string suffix_;  // the end of the string, then the other members less the closing brace
  std::function<void(nlohmann::json&)> after_;
};

}  // namespace

std::unique_ptr<domain::TextSource> json_with_streamed_string(
    std::string_view key, std::unique_ptr<domain::TextSource> value, nlohmann::json rest,
    std::function<void(nlohmann::json&)> after) {
  return std::make_unique<StreamedJsonString>(key, std::move(value), rest, std::move(after));
}

}  // namespace cutcalc::api
