#include "domain/program/block_words.h"

#include <utility>

namespace cutcalc::domain::program {

BlockWords::BlockWords(ProgramOptions options)
    : options_(std::move(options)),
      decimals_(decimals_of(options_)),
      words_(words_of(options_.dialect)) {}

std::size_t BlockWords::held_bytes() const {
  return options_.name.capacity() + last_feed_.capacity();
}

void BlockWords::line(std::string_view text) {
  text_->append(text);
  text_->push_back('\n');
}

std::string BlockWords::length(double mm) const {
  return format_fixed(to_program_units(mm, options_.units), decimals_);
}

void BlockWords::feed_line(std::string move, const std::string& printed_feed) {
  if (printed_feed != last_feed_) {
    move.append(" F").append(printed_feed);
    last_feed_ = printed_feed;
  }
  line(move);
}

void BlockWords::block(const SpindleOff&) {
  if (text_ != nullptr) line(words_.spindle_off);
}

void BlockWords::block(const CoolantOn& on) {
  if (text_ != nullptr) line(on.coolant == Coolant::mist ? words_.mist : words_.flood);
}

void BlockWords::block(const CoolantOff&) {
  if (text_ != nullptr) line(words_.coolant_off);
}

}  // namespace cutcalc::domain::program
