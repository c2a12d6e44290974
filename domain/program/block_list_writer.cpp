#include "domain/program/block_list_writer.h"

#include <algorithm>

#include "domain/common/interruption.h"

namespace cutcalc::domain::program {

bool BlockListWriter::write_next(std::string& text, std::size_t max_bytes) {
  const std::size_t until = text.size() + std::max<std::size_t>(max_bytes, 1);
  switch (part_) {
    case Part::header:
      write_header(text);
      part_ = Part::blocks;
      [[fallthrough]];
    case Part::blocks:
      for (const std::size_t count = block_count(); next_ < count; ++next_) {
        if (text.size() >= until) return true;
        interruption_point();
        write_block(next_, text);
      }
      write_end(text);
      part_ = Part::done;
      return false;
    case Part::done:
      break;
  }
  return false;
}

}  // namespace cutcalc::domain::program
