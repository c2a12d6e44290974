#pragma once
// A text written piece by piece as it is read (a program of many megabytes): whoever sends it asks
// for the next piece only when the previous one has gone, so what is held at any moment is the
// generator's state and one piece, never the whole text.

#include <cstddef>
#include <string>
#include <utility>

namespace cutcalc::domain {

class TextSource {
 public:
  TextSource() = default;
  TextSource(const TextSource&) = delete;
  TextSource& operator=(const TextSource&) = delete;
  virtual ~TextSource() = default;

  // Appends the next piece to `out`: at least one byte unless the text has ended, about
  // `max_bytes` (a line may go past it). False once the text has ended (nothing more to append).
  // May throw; the text is then incomplete.
  virtual bool write_next(std::string& out, std::size_t max_bytes) = 0;
  // What the source holds besides the pieces it hands out, in bytes (for a memory budget).
  [[nodiscard]] virtual std::size_t held_bytes() const = 0;
};

// The whole rest of `source` appended to `out` (a caller that needs the text at once).
void write_all(TextSource& source, std::string& out);

// A text that is already whole, handed out in pieces.
class StringSource final : public TextSource {
 public:
  explicit StringSource(std::string text) : text_(std::move(text)) {}
  bool write_next(std::string& out, std::size_t max_bytes) override;
  [[nodiscard]] std::size_t held_bytes() const override { return sizeof(*this) + text_.capacity(); }

 private:
  std::string text_;
  std::size_t sent_ = 0;
};

}  // namespace cutcalc::domain
