#pragma once
// The text rules of spec programs.md section 3 that hold for every program of a dialect (pass
// programs, polygon programs with a `program` object, lathe programs of grooving-cycle.md 5.2),
// as gtest expectations.

#include <string>

namespace cutcalc::testing {

// ASCII, LF; comments in the dialect's form (fanuc upper case), nothing forbidden inside; no -0;
// a decimal point in every X Y Z I J C F; one M word per block; fanuc: %, O{4 digits} (NAME),
// G21/G20 alone first, two-digit G and M words, an integer S (and lathe G50 S), M30 and %;
// sinumerik: `; NAME`, G710/G700, no % or parentheses, M30 last; linuxcnc: % first, M30 and %
// last.
void expect_text_rules(const std::string& program, const std::string& dialect);

}  // namespace cutcalc::testing
