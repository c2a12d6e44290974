#include "domain/common/text_source.h"

#include <algorithm>

namespace cutcalc::domain {

void write_all(TextSource& source, std::string& out) {
  constexpr std::size_t kPiece = 1 << 20;
  while (source.write_next(out, kPiece)) {
  }
}

bool StringSource::write_next(std::string& out, std::size_t max_bytes) {
  const std::size_t n = std::min(max_bytes, text_.size() - sent_);
  out.append(text_, sent_, n);
  sent_ += n;
  if (sent_ < text_.size()) return true;
  std::string().swap(text_);
  sent_ = 0;
  return false;
}

}  // namespace cutcalc::domain
