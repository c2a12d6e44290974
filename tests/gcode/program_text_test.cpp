// The translation of lathe programs to LinuxCNC (spec grooving-cycle.md section 5.4), word by
// word, on short hand-written programs; the milling forms keep theirs (programs.md section 3).

#include <gtest/gtest.h>

#include <string>

#include "gcode/program_text.h"

namespace {

using cutcalc::test::gcode::translate_to_linuxcnc;

TEST(ProgramText, FanucLatheFormsBecomeLinuxcncWords) {
  const std::string fanuc =
      "%\nO0001 (NAME)\n(COMMENT)\nG21\nG18 G40 G99\nG54\nT0707\nG00 X52.000 Z-12.500\n"
      "G50 S2500\nG96 S150 M03\nG01 X50.000 F0.100\nG04 X0.461\nG00 X52.000\nM05\nM30\n%\n";
  EXPECT_EQ(translate_to_linuxcnc(fanuc, "fanuc"),
            "%\n(COMMENT)\nG21\nG18 G40 G7 G95\nG54\nT7 M6 G43\nG0 X52.000 Z-12.500\n"
            "G96 D2500 S150 M3\nG1 X50.000 F0.100\nG4 P0.461\nG0 X52.000\nM5\nM30\n%\n");
}

TEST(ProgramText, SinumerikLatheFormsBecomeLinuxcncWords) {
  const std::string sinumerik =
      "; NAME\n; COMMENT\nG18 G710 G40 G90 G95 DIAMON\nG54\nT12 D1\nG0 X52.000 Z-12.500\n"
      "G96 S150.000 LIMS=2500.000 M3\nG1 X50.000 F0.100\nG4 F0.461\nM5\nM30\n";
  EXPECT_EQ(translate_to_linuxcnc(sinumerik, "sinumerik"),
            "(NAME)\n(COMMENT)\nG18 G21 G40 G90 G95 G7\nG54\nT12 M6 G43\nG0 X52.000 Z-12.500\n"
            "G96 S150.000 D2500.000 M3\nG1 X50.000 F0.100\nG4 P0.461\nM5\nM30\n");
}

TEST(ProgramText, MillingToolCallsKeepTheirTranslation) {
  EXPECT_EQ(translate_to_linuxcnc("T7 M06\nG43 H07\n", "fanuc"), "T7 M6\nG43 H07\n");
  EXPECT_EQ(translate_to_linuxcnc("T7\nM6\nD1\nG4 F2.0\n", "sinumerik"), "T7\nM6\nG4 P2.0\n");
}

}  // namespace
