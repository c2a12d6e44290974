#pragma once
// A program's text written as it is read: its header, its blocks from the next one on, its end.
// The milling (dialect_writer) and lathe (lathe_program) writers differ only in the wording.

#include <cstddef>
#include <string>

#include "domain/common/text_source.h"

namespace cutcalc::domain::program {

class BlockListWriter : public TextSource {
 public:
  // Every block writes a line: at least one byte unless the text has ended.
  bool write_next(std::string& text, std::size_t max_bytes) final;

 protected:
  BlockListWriter() = default;

  virtual void write_header(std::string& text) = 0;
  [[nodiscard]] virtual std::size_t block_count() const = 0;
  virtual void write_block(std::size_t index, std::string& text) = 0;
  virtual void write_end(std::string& text) = 0;

 private:
  enum class Part { header, blocks, done };

  Part part_ = Part::header;
  std::size_t next_ = 0;  // the next block to write
};

}  // namespace cutcalc::domain::program
