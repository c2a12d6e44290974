// The lathe program writer (domain/program/lathe_program.h; grooving-cycle.md section 5.2, and
// programs.md section 3 for what it shares with the milling programs): per dialect, the header,
// tool call, spindle lines, dwell words, inch conversion, F only on change, no -0, and the Fanuc
// integer S words.

#include "domain/program/lathe_program.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "domain/program/lathe_dialect.h"

namespace cutcalc::domain::program {
namespace {

// Modal lines of the same shape as the grooving program's (section 5.2).
constexpr LatheModalLines kModal{"{units} G18 G7 G90 G40 G49 G80 G95", "{units}\nG18 G40 G99",
                                 "G18 {units} G40 G90 G95 DIAMON"};

ProgramOptions options_for(Dialect dialect, Units units = Units::mm) {
  ProgramOptions options;
  options.dialect = dialect;
  options.units = units;
  return options;
}

std::string text_of(const std::vector<LatheBlock>& blocks, const ProgramOptions& options,
                    std::vector<std::string> comments = {}) {
  LatheProgram program;
  program.comments = std::move(comments);
  program.modal = kModal;
  program.blocks = blocks;
  const auto text = write_lathe_program(program, options);
  EXPECT_TRUE(text.ok());
  return text.ok() ? text.value() : std::string{};
}

// The body between the header (through the work offset and tool call) and the end words.
std::string body_of(const std::vector<LatheBlock>& blocks, const ProgramOptions& options) {
  const std::string empty = text_of({}, options);
  const std::string full = text_of(blocks, options);
  const std::string end = options.dialect == Dialect::sinumerik ? "M30\n" : "M30\n%\n";
  EXPECT_EQ(empty.substr(empty.size() - end.size()), end);
  const std::size_t header = empty.size() - end.size();
  return full.substr(header, full.size() - header - end.size());
}

TEST(LatheProgramHeader, LinuxcncMmAndInchAsSection52) {
  ProgramOptions options = options_for(Dialect::linuxcnc);
  options.name = "GROOVE";
  options.tool_number = 7;
  EXPECT_EQ(text_of({}, options, {"A TITLE"}),
            "%\n(GROOVE)\n(A TITLE)\nG21 G18 G7 G90 G40 G49 G80 G95\nG54\nT7 M6 G43\nM30\n%\n");
  options.units = Units::inch;
  options.tool_number.reset();
  options.work_offset = 59;
  EXPECT_EQ(text_of({}, options, {"A TITLE"}),
            "%\n(GROOVE)\n(A TITLE)\nG20 G18 G7 G90 G40 G49 G80 G95\nG59\nM30\n%\n");
}

TEST(LatheProgramHeader, FanucMmAndInchAsSection52) {
  ProgramOptions options = options_for(Dialect::fanuc);
  options.program_number = 321;
  options.tool_number = 7;
  EXPECT_EQ(text_of({}, options, {"a title"}),
            "%\nO0321 (CUTCALC)\n(A TITLE)\nG21\nG18 G40 G99\nG54\nT0707\nM30\n%\n");
  options.units = Units::inch;
  options.tool_number = 12;
  EXPECT_EQ(text_of({}, options, {"a title"}),
            "%\nO0321 (CUTCALC)\n(A TITLE)\nG20\nG18 G40 G99\nG54\nT1212\nM30\n%\n");
}

TEST(LatheProgramHeader, SinumerikMmAndInchAsSection52) {
  ProgramOptions options = options_for(Dialect::sinumerik);
  options.name = "GROOVE_1";
  options.tool_number = 7;
  options.work_offset = 57;
  EXPECT_EQ(text_of({}, options, {"A TITLE"}),
            "; GROOVE_1\n; A TITLE\nG18 G710 G40 G90 G95 DIAMON\nG57\nT7 D1\nM30\n");
  options.units = Units::inch;
  EXPECT_EQ(text_of({}, options, {"A TITLE"}),
            "; GROOVE_1\n; A TITLE\nG18 G700 G40 G90 G95 DIAMON\nG57\nT7 D1\nM30\n");
}

TEST(LatheDialect, ToolCallFormsPerDialect) {
  EXPECT_EQ(lathe_tool_call(7, Dialect::linuxcnc), "T7 M6 G43");
  EXPECT_EQ(lathe_tool_call(7, Dialect::fanuc), "T0707");
  EXPECT_EQ(lathe_tool_call(99, Dialect::fanuc), "T9999");
  EXPECT_EQ(lathe_tool_call(7, Dialect::sinumerik), "T7 D1");
}

TEST(LatheProgramSpindle, ConstantSpeedLinePerDialect) {
  const std::vector<LatheBlock> blocks{ConstantSpindleSpeed{500.4}};
  EXPECT_EQ(body_of(blocks, options_for(Dialect::linuxcnc)), "G97 S500.4000 M3\n");
  EXPECT_EQ(body_of(blocks, options_for(Dialect::fanuc)), "G97 S500 M03\n");
  EXPECT_EQ(body_of(blocks, options_for(Dialect::sinumerik)), "G97 S500.400 M3\n");
  // rpm is not a length: unchanged in inch.
  EXPECT_EQ(body_of(blocks, options_for(Dialect::linuxcnc, Units::inch)), "G97 S500.40000 M3\n");
}

TEST(LatheProgramSpindle, ConstantSurfaceSpeedLinePerDialectWithItsLimit) {
  const std::vector<LatheBlock> blocks{ConstantSurfaceSpeed{86.0, 1000.0}};
  EXPECT_EQ(body_of(blocks, options_for(Dialect::linuxcnc)), "G96 D1000.0000 S86.0000 M3\n");
  EXPECT_EQ(body_of(blocks, options_for(Dialect::fanuc)), "G50 S1000\nG96 S86 M03\n");
  EXPECT_EQ(body_of(blocks, options_for(Dialect::sinumerik)), "G96 S86.000 LIMS=1000.000 M3\n");
  // Inch: v in ft/min = 86/0.3048 = 282.152231; the limit stays in rpm.
  EXPECT_EQ(body_of(blocks, options_for(Dialect::linuxcnc, Units::inch)),
            "G96 D1000.00000 S282.15223 M3\n");
  EXPECT_EQ(body_of(blocks, options_for(Dialect::fanuc, Units::inch)), "G50 S1000\nG96 S282 M03\n");
  EXPECT_EQ(body_of(blocks, options_for(Dialect::sinumerik, Units::inch)),
            "G96 S282.1522 LIMS=1000.0000 M3\n");
  EXPECT_NEAR(surface_speed_in_program_units(86.0, Units::inch), 282.1522309711286, 1e-9);
  EXPECT_EQ(surface_speed_in_program_units(86.0, Units::mm), 86.0);
}

TEST(LatheProgramDwell, DwellWordsInSecondsPerDialectAndUnit) {
  const std::vector<LatheBlock> blocks{Dwell{0.4616}};
  EXPECT_EQ(body_of(blocks, options_for(Dialect::linuxcnc)), "G4 P0.462\n");
  EXPECT_EQ(body_of(blocks, options_for(Dialect::fanuc)), "G04 X0.462\n");
  EXPECT_EQ(body_of(blocks, options_for(Dialect::sinumerik)), "G4 F0.462\n");
  // Seconds in inch too, always 3 decimals.
  EXPECT_EQ(body_of(blocks, options_for(Dialect::linuxcnc, Units::inch)), "G4 P0.462\n");
  ProgramOptions six = options_for(Dialect::fanuc);
  six.decimals = 6;
  EXPECT_EQ(body_of(blocks, six), "G04 X0.462\n");
}

TEST(LatheProgramMotion, InchConvertsLengthsAndFeedsPerRevolution) {
  const std::vector<LatheBlock> blocks{LatheRapid{{50.8, -25.4}},
                                       LatheFeed{{25.4, std::nullopt}, 0.254},
                                       LatheFeed{{std::nullopt, 12.7}, 0.254}};
  EXPECT_EQ(body_of(blocks, options_for(Dialect::linuxcnc, Units::inch)),
            "G0 X2.00000 Z-1.00000\nG1 X1.00000 F0.01000\nG1 Z0.50000\n");
  EXPECT_EQ(body_of(blocks, options_for(Dialect::fanuc, Units::inch)),
            "G00 X2.0000 Z-1.0000\nG01 X1.0000 F0.0100\nG01 Z0.5000\n");
  EXPECT_EQ(body_of(blocks, options_for(Dialect::sinumerik)),
            "G0 X50.800 Z-25.400\nG1 X25.400 F0.254\nG1 Z12.700\n");
}

TEST(LatheProgramMotion, FeedIsPrintedOnlyWhenItsPrintedValueChanges) {
  // 0.10001 prints as 0.1000 like 0.1: no F; 0.2 does; back to 0.1 does again.
  const std::vector<LatheBlock> blocks{
      LatheFeed{{49.0, std::nullopt}, 0.1}, LatheFeed{{48.0, std::nullopt}, 0.10001},
      LatheFeed{{47.0, 1.0}, 0.2}, LatheFeed{{46.0, std::nullopt}, 0.1}};
  EXPECT_EQ(body_of(blocks, options_for(Dialect::linuxcnc)),
            "G1 X49.0000 F0.1000\nG1 X48.0000\nG1 X47.0000 Z1.0000 F0.2000\nG1 X46.0000 "
            "F0.1000\n");
}

TEST(LatheProgramMotion, NoNegativeZeroIsPrinted) {
  const std::vector<LatheBlock> blocks{LatheRapid{{-0.00001, -0.00004}},
                                       LatheFeed{{std::nullopt, -0.0}, 0.1}};
  EXPECT_EQ(body_of(blocks, options_for(Dialect::linuxcnc)),
            "G0 X0.0000 Z0.0000\nG1 Z0.0000 F0.1000\n");
  EXPECT_EQ(body_of(blocks, options_for(Dialect::fanuc)), "G00 X0.000 Z0.000\nG01 Z0.000 F0.100\n");
}

TEST(LatheProgramMotion, CoolantAndSpindleOffWordsPerDialect) {
  const std::vector<LatheBlock> blocks{CoolantOn{Coolant::flood}, CoolantOn{Coolant::mist},
                                       SpindleOff{}, CoolantOff{}};
  EXPECT_EQ(body_of(blocks, options_for(Dialect::linuxcnc)), "M8\nM7\nM5\nM9\n");
  EXPECT_EQ(body_of(blocks, options_for(Dialect::fanuc)), "M08\nM07\nM05\nM09\n");
  EXPECT_EQ(body_of(blocks, options_for(Dialect::sinumerik)), "M8\nM7\nM5\nM9\n");
}

TEST(LatheProgramErrors, FeedSpindleAndDwellWordsThatPrintAsZeroAreRefused) {
  const auto refused = [](const LatheBlock& block, const ProgramOptions& options) {
    LatheProgram program;
    program.modal = kModal;
    program.blocks = {block};
    const auto text = write_lathe_program(program, options);
    return !text.ok() && text.error().code == ErrorCode::word_prints_as_zero;
  };
  const ProgramOptions linuxcnc = options_for(Dialect::linuxcnc);
  const ProgramOptions fanuc = options_for(Dialect::fanuc);
  EXPECT_TRUE(refused(LatheFeed{{1.0, std::nullopt}, 0.00004}, linuxcnc));
  EXPECT_FALSE(refused(LatheFeed{{1.0, std::nullopt}, 0.00005}, linuxcnc));  // 0.0001
  EXPECT_TRUE(refused(Dwell{0.0004}, linuxcnc));
  EXPECT_FALSE(refused(Dwell{0.0005}, linuxcnc));
  EXPECT_TRUE(refused(ConstantSpindleSpeed{0.4}, fanuc));
  EXPECT_FALSE(refused(ConstantSpindleSpeed{0.5}, fanuc));        // half up: S1
  EXPECT_TRUE(refused(ConstantSurfaceSpeed{86.0, 0.99}, fanuc));  // G50 S0
  EXPECT_TRUE(refused(ConstantSurfaceSpeed{0.4, 1000.0}, fanuc));
  EXPECT_TRUE(refused(ConstantSurfaceSpeed{86.0, 0.00004}, linuxcnc));  // D
  EXPECT_TRUE(refused(ConstantSurfaceSpeed{0.0004, 1000.0}, options_for(Dialect::sinumerik)));
  EXPECT_TRUE(refused(ConstantSurfaceSpeed{86.0, 0.0004}, options_for(Dialect::sinumerik)));
  // Positions may print as zero.
  EXPECT_FALSE(refused(LatheRapid{{0.0, 0.0}}, linuxcnc));
}

TEST(LatheProgramRotary, CWordsAreDegreesUnconvertedAndNeverWrapped) {
  // lathe-flat.md 6.3: C in degrees, absolute, with `decimals`; inch converts X only; no -0.
  const std::vector<LatheBlock> blocks{LatheRapid{{std::nullopt, std::nullopt, 20.36413}},
                                       LatheRapid{{50.8, std::nullopt, -380.5}},
                                       LatheRapid{{std::nullopt, std::nullopt, -0.000001}}};
  EXPECT_EQ(body_of(blocks, options_for(Dialect::linuxcnc)),
            "G0 C20.3641\nG0 X50.8000 C-380.5000\nG0 C0.0000\n");
  EXPECT_EQ(body_of(blocks, options_for(Dialect::linuxcnc, Units::inch)),
            "G0 C20.36413\nG0 X2.00000 C-380.50000\nG0 C0.00000\n");
  EXPECT_EQ(body_of(blocks, options_for(Dialect::sinumerik)),
            "G0 C20.364\nG0 X50.800 C-380.500\nG0 C0.000\n");
}

TEST(LatheProgramRotary, InverseTimeBlocksCarryTheirOwnFeedUnconverted) {
  // lathe-flat.md 6.1-6.3: every G93 block writes F = 1/T (per minute, not converted to inch),
  // also when it repeats; G94 afterwards makes the next per-minute feed write its F again.
  const std::vector<LatheBlock> blocks{LatheFeed{{32.0, std::nullopt}, 100.0},
                                       FeedModeChange{FeedMode::inverse_time},
                                       InverseTimeFeed{{31.6, std::nullopt, 10.0}, 187.5},
                                       InverseTimeFeed{{30.0, std::nullopt, 0.0}, 187.5},
                                       FeedModeChange{FeedMode::per_minute},
                                       LatheFeed{{32.0, std::nullopt}, 100.0}};
  EXPECT_EQ(body_of(blocks, options_for(Dialect::linuxcnc)),
            "G1 X32.0000 F100.0000\nG93\nG1 X31.6000 C10.0000 F187.5000\n"
            "G1 X30.0000 C0.0000 F187.5000\nG94\nG1 X32.0000 F100.0000\n");
  EXPECT_EQ(body_of(blocks, options_for(Dialect::linuxcnc, Units::inch)),
            "G1 X1.25984 F3.93701\nG93\nG1 X1.24409 C10.00000 F187.50000\n"
            "G1 X1.18110 C0.00000 F187.50000\nG94\nG1 X1.25984 F3.93701\n");
  EXPECT_EQ(body_of(blocks, options_for(Dialect::sinumerik)),
            "G1 X32.000 F100.000\nG93\nG1 X31.600 C10.000 F187.500\n"
            "G1 X30.000 C0.000 F187.500\nG94\nG1 X32.000 F100.000\n");
}

TEST(LatheProgramRotary, AnInverseTimeFeedThatPrintsAsZeroIsRefused) {
  LatheProgram program;
  program.modal = kModal;
  program.blocks = {FeedModeChange{FeedMode::inverse_time},
                    InverseTimeFeed{{30.0, std::nullopt, 1.0}, 0.00004}};
  const auto refused = write_lathe_program(program, options_for(Dialect::linuxcnc));
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, ErrorCode::word_prints_as_zero);
  program.blocks = {FeedModeChange{FeedMode::inverse_time},
                    InverseTimeFeed{{30.0, std::nullopt, 1.0}, 0.00005}};  // F0.0001
  EXPECT_TRUE(write_lathe_program(program, options_for(Dialect::linuxcnc)).ok());
}

TEST(LatheProgramText, WrittenPieceByPieceIsTheWholeTextInEveryDialect) {
  auto program = std::make_shared<LatheProgram>();
  program->comments = {"A TITLE"};
  program->modal = kModal;
  program->blocks = {LatheRapid{{40.0, 2.0}},
                     ConstantSurfaceSpeed{86.0, 1000.0},
                     CoolantOn{Coolant::flood},
                     LatheFeed{{30.0, std::nullopt}, 0.1},
                     LatheFeed{{29.0, std::nullopt}, 0.1},
                     FeedModeChange{FeedMode::inverse_time},
                     InverseTimeFeed{{28.0, std::nullopt, 10.0}, 187.5},
                     FeedModeChange{FeedMode::per_minute},
                     LatheFeed{{29.0, std::nullopt}, 0.1},
                     Dwell{0.5},
                     ConstantSpindleSpeed{500.0},
                     SpindleOff{},
                     CoolantOff{}};
  for (const Dialect dialect : {Dialect::linuxcnc, Dialect::fanuc, Dialect::sinumerik}) {
    ProgramOptions options = options_for(dialect);
    options.tool_number = 3;
    const auto whole = write_lathe_program(*program, options);
    ASSERT_TRUE(whole.ok());
    for (const std::size_t piece : {std::size_t{0}, std::size_t{1}, std::size_t{30}}) {
      const auto source = open_lathe_program(program, options);
      EXPECT_GT(source->held_bytes(), 0U);
      std::string text;
      std::size_t calls = 0;
      while (source->write_next(text, piece)) ++calls;
      EXPECT_EQ(text, whole.value()) << piece;
      if (piece <= 1) {
        EXPECT_EQ(calls, program->blocks.size()) << piece;  // a block a piece
      }
      EXPECT_FALSE(source->write_next(text, piece));  // ended: nothing more
      EXPECT_EQ(text.size(), whole.value().size());
    }
  }
}

TEST(LatheProgramErrors, TheFirstWordThatPrintsAsZeroIsNamedBeforeAnyTextIsWritten) {
  LatheProgram program;
  program.modal = kModal;
  program.blocks = {LatheFeed{{1.0, std::nullopt}, 0.1}, Dwell{0.0001},
                    LatheFeed{{1.0, std::nullopt}, 0.00001}};
  const auto error = lathe_program_error(program, options_for(Dialect::linuxcnc));
  ASSERT_TRUE(error.has_value());
  EXPECT_EQ(error->code, ErrorCode::word_prints_as_zero);
  EXPECT_EQ(error->detail, "G4 would print as zero with these decimals");
  program.blocks.resize(1);
  EXPECT_FALSE(lathe_program_error(program, options_for(Dialect::linuxcnc)).has_value());
}

TEST(FanucSpindleWords, SpeedsRoundHalfUpAndTheLimitFloors) {
  FanucSpindleWords words = fanuc_spindle_words(ConstantSpindleSpeed{500.5});
  EXPECT_EQ(words.s, 501.0);
  EXPECT_TRUE(words.rounded);
  EXPECT_FALSE(words.clamp_rpm.has_value());
  words = fanuc_spindle_words(ConstantSpindleSpeed{500.4999});
  EXPECT_EQ(words.s, 500.0);
  EXPECT_TRUE(words.rounded);
  words = fanuc_spindle_words(ConstantSpindleSpeed{500.0});
  EXPECT_EQ(words.s, 500.0);
  EXPECT_FALSE(words.rounded);
  // Within 1e-9 counts as not rounded.
  EXPECT_FALSE(fanuc_spindle_words(ConstantSpindleSpeed{500.0 + 1e-11}).rounded);

  words = fanuc_spindle_words(ConstantSurfaceSpeed{86.5, 1000.9}, Units::mm);
  EXPECT_EQ(words.s, 87.0);
  ASSERT_TRUE(words.clamp_rpm.has_value());
  EXPECT_EQ(*words.clamp_rpm, 1000.0);  // never above the limit
  EXPECT_TRUE(words.rounded);
  words = fanuc_spindle_words(ConstantSurfaceSpeed{86.0, 1000.0}, Units::mm);
  EXPECT_EQ(words.s, 86.0);
  EXPECT_EQ(*words.clamp_rpm, 1000.0);
  EXPECT_FALSE(words.rounded);
  // Only the limit rounded.
  EXPECT_TRUE(fanuc_spindle_words(ConstantSurfaceSpeed{86.0, 999.5}, Units::mm).rounded);
  // Inch: ft/min. 86 m/min = 282.15 ft/min -> 282, rounded; 91.44 m/min = 300 ft/min, not.
  words = fanuc_spindle_words(ConstantSurfaceSpeed{86.0, 1000.0}, Units::inch);
  EXPECT_EQ(words.s, 282.0);
  EXPECT_TRUE(words.rounded);
  words = fanuc_spindle_words(ConstantSurfaceSpeed{91.44, 1000.0}, Units::inch);
  EXPECT_EQ(words.s, 300.0);
  EXPECT_FALSE(words.rounded);
}

}  // namespace
}  // namespace cutcalc::domain::program
