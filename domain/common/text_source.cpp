#include "domain/common/text_source.h"

namespace cutcalc::domain {

void write_all(TextSource& source, std::string& out) {
  constexpr std::size_t kPiece = 1 << 20;
  while (source.write_next(out, kPiece)) {
  }
}

}  // namespace cutcalc::domain
