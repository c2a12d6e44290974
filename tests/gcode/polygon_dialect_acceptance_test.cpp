// The polygon program in every dialect and in inches (spec programs.md sections 2-4): each one,
// translated to LinuxCNC as section 3 says, is accepted by rs274 and moves exactly as today's
// program, the one the path and kink checker of linuxcnc_acceptance_test.cpp accepts:
//  - mm at 4 decimals: the same canonical STRAIGHT_TRAVERSE / STRAIGHT_FEED / ARC_FEED sequence
//    (and SET_FEED_RATE, except fanuc's ramp loops, which take the flat F by design);
//  - inch: the same sequence of moves, every coordinate x 25.4 within the printed rounding of
//    both programs (rs274 prints 4 decimals: 0.5e-4 in = 0.00127 mm) plus 0.0001 mm.

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "domain/polygon/polygon_hole.h"
#include "gcode/program_text.h"
#include "gcode/rs274_runner.h"

namespace {

using cutcalc::domain::polygon::generate_polygon_hole;
using cutcalc::domain::polygon::PolygonHoleParams;
using cutcalc::domain::polygon::Synchronization;
using cutcalc::test::gcode::Rs274Run;
using cutcalc::test::gcode::run_rs274;
using cutcalc::test::gcode::translate_to_linuxcnc;
namespace program = cutcalc::domain::program;

struct Command {
  std::string name;  // STRAIGHT_TRAVERSE, STRAIGHT_FEED, ARC_FEED, SET_FEED_RATE
  std::vector<double> args;
};

std::vector<Command> canonical(const std::string& output) {
  std::vector<Command> commands;
  std::istringstream in(output);
  std::string line;
  while (std::getline(in, line)) {
    for (const char* name :
         {"STRAIGHT_TRAVERSE(", "STRAIGHT_FEED(", "ARC_FEED(", "SET_FEED_RATE("}) {
      const auto at = line.find(name);
      if (at == std::string::npos) continue;
      Command command{std::string(name, std::string(name).size() - 1), {}};
      std::istringstream args(line.substr(at + command.name.size() + 1));
      std::string value;
      while (std::getline(args, value, ','))
        command.args.push_back(std::strtod(value.c_str(), nullptr));
      commands.push_back(command);
    }
  }
  return commands;
}

std::vector<Command> run(const std::string& text, const std::string& dialect) {
  const Rs274Run result = run_rs274(translate_to_linuxcnc(text, dialect));
  EXPECT_TRUE(result.started) << result.spawn_error;
  EXPECT_EQ(result.exit_code, 0) << dialect << ": " << result.errors;
  return canonical(result.output);
}

PolygonHoleParams hole(int faces, Synchronization sync) {
  PolygonHoleParams params;
  params.faces = faces;
  params.inscribed_diameter_mm = faces == 4 ? 16.0 : 20.0;
  params.depth_mm = 0.2;
  params.step_down_mm = 0.1;
  params.spindle_speed_rpm = 40.0;
  params.tolerance_mm = 0.001;
  params.synchronization = sync;
  return params;
}

std::string write(PolygonHoleParams params, std::optional<program::ProgramOptions> options) {
  params.program = options;
  const auto result = generate_polygon_hole(params);
  EXPECT_TRUE(result.ok());
  return result.ok() ? cutcalc::domain::polygon::program_text(result.value()) : std::string();
}

std::string name_of(const std::string& dialect) {
  return dialect == "fanuc" ? "fanuc" : dialect == "sinumerik" ? "sinumerik" : "linuxcnc";
}

program::Dialect dialect_of(const std::string& name) {
  return name == "fanuc"       ? program::Dialect::fanuc
         : name == "sinumerik" ? program::Dialect::sinumerik
                               : program::Dialect::linuxcnc;
}

TEST(PolygonDialectAcceptance, MmProgramsMoveExactlyAsTodaysProgram) {
  for (const int faces : {3, 4, 6}) {
    for (const Synchronization sync : {Synchronization::feed_per_rev, Synchronization::c_axis}) {
      const PolygonHoleParams params = hole(faces, sync);
      const std::vector<Command> today = run(write(params, std::nullopt), "linuxcnc");
      ASSERT_FALSE(today.empty());
      for (const std::string dialect : {"linuxcnc", "fanuc", "sinumerik"}) {
        SCOPED_TRACE("N=" + std::to_string(faces) + " " +
                     (sync == Synchronization::c_axis ? "c_axis " : "feed_per_rev ") + dialect);
        program::ProgramOptions options;
        options.dialect = dialect_of(dialect);
        options.decimals = 4;
        options.safe_z_mm = params.safe_z_mm;
        const std::vector<Command> other = run(write(params, options), name_of(dialect));
        const bool compare_feeds = !(dialect == "fanuc" && sync == Synchronization::feed_per_rev);
        const auto moves = [&](const std::vector<Command>& all) {
          std::vector<Command> kept;
          for (const Command& c : all) {
            if (compare_feeds || c.name != "SET_FEED_RATE") kept.push_back(c);
          }
          return kept;
        };
        const auto a = moves(today);
        const auto b = moves(other);
        ASSERT_EQ(a.size(), b.size());
        for (std::size_t i = 0; i < a.size(); ++i) {
          ASSERT_EQ(a[i].name, b[i].name) << i;
          EXPECT_EQ(a[i].args, b[i].args) << a[i].name << " #" << i;
        }
      }
    }
  }
}

TEST(PolygonDialectAcceptance, InchProgramsMoveAsTodaysWithinThePrintedRounding) {
  constexpr double kTolerance = 25.4 * 0.5e-4 + 25.4 * 0.5e-5 + 0.0001;
  for (const int faces : {3, 4}) {
    const PolygonHoleParams params = hole(faces, Synchronization::feed_per_rev);
    const std::vector<Command> today = run(write(params, std::nullopt), "linuxcnc");
    for (const std::string dialect : {"linuxcnc", "fanuc", "sinumerik"}) {
      SCOPED_TRACE("N=" + std::to_string(faces) + " inch " + dialect);
      program::ProgramOptions options;
      options.dialect = dialect_of(dialect);
      options.units = program::Units::inch;
      options.decimals = 5;
      options.safe_z_mm = params.safe_z_mm;
      const std::vector<Command> other = run(write(params, options), name_of(dialect));
      std::vector<const Command*> a;
      std::vector<const Command*> b;
      for (const Command& c : today)
        if (c.name != "SET_FEED_RATE") a.push_back(&c);
      for (const Command& c : other)
        if (c.name != "SET_FEED_RATE") b.push_back(&c);
      ASSERT_EQ(a.size(), b.size());
      double worst = 0.0;
      for (std::size_t i = 0; i < a.size(); ++i) {
        ASSERT_EQ(a[i]->name, b[i]->name) << i;
        // X, Y, Z of the end (and the arc centre): every argument but the arc's turn and the
        // rotary axes, which keep their units.
        const std::size_t n = std::min<std::size_t>(a[i]->args.size(), 6);
        for (std::size_t k = 0; k < n; ++k) {
          if (a[i]->name == "ARC_FEED" && k == 4) continue;  // the turn count
          if (a[i]->name != "ARC_FEED" && k >= 3) continue;  // A B C
          worst = std::max(worst, std::fabs(a[i]->args[k] - 25.4 * b[i]->args[k]));
        }
      }
      EXPECT_LE(worst, kTolerance);
    }
  }
}

}  // namespace
