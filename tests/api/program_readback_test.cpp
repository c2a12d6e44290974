// Every program cutcalc writes reads back (spec machine-time.md section 4: "the reader accepts
// every program cutcalc writes"): for each endpoint that answers with a program (api/routes.h,
// json_and_plain_text_program), each 200 reference request, as given and once in each dialect the
// endpoint accepts (a 422 for a dialect is skipped), goes through the endpoint's handler; its
// program (the text/plain form, and the JSON answer's `program` when it has one) must read without
// a refusal in the request's dialect, on a lathe for the lathe endpoints, give moves, and end
// where the program's last X, Y, Z and C words say.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "api/routes.h"
#include "domain/machine_time/gcode_reader.h"
#include "support/test_server.h"

namespace cutcalc::testing {
namespace {

using domain::machine_time::Axis;
using domain::machine_time::AxisVector;
using domain::machine_time::MachineKind;
using domain::machine_time::Move;
using domain::machine_time::MoveKind;
using domain::machine_time::ReadError;
using domain::machine_time::ReadOptions;
using domain::machine_time::ReadSummary;
using domain::program::Dialect;
using nlohmann::json;

constexpr std::array<std::string_view, 3> kDialects = {"linuxcnc", "fanuc", "sinumerik"};

Dialect dialect_of(std::string_view name) {
  if (name == "fanuc") return Dialect::fanuc;
  if (name == "sinumerik") return Dialect::sinumerik;
  return Dialect::linuxcnc;
}

// The last value of each of X, Y, Z and C that the program's motion blocks write (every program
// cutcalc writes is absolute), read from the text with none of the reader's code.
struct LastWords {
  std::array<std::optional<double>, 4> value;  // X Y Z C
};

LastWords last_words(std::string_view program, Dialect dialect) {
  LastWords last;
  std::size_t at = 0;
  while (at < program.size()) {
    std::size_t end = program.find('\n', at);
    if (end == std::string_view::npos) end = program.size();
    std::string line(program.substr(at, end - at));
    at = end + 1;
    // Comments: ( ... ) outside Sinumerik, ; to the end of the line.
    if (dialect != Dialect::sinumerik) {
      for (std::size_t open = line.find('('); open != std::string::npos; open = line.find('(')) {
        line.erase(open, line.find(')', open) - open + 1);
      }
    }
    if (const std::size_t semicolon = line.find(';'); semicolon != std::string::npos) {
      line.erase(semicolon);
    }
    // A dwell's X is its time.
    if (line.find("G4 ") != std::string::npos || line.find("G04 ") != std::string::npos) continue;
    for (std::size_t k = 0; k < line.size(); ++k) {
      const std::size_t slot = std::string_view("XYZC").find(line[k]);
      if (slot == std::string_view::npos || (k > 0 && line[k - 1] != ' ')) continue;
      std::size_t used = 0;
      last.value[slot] = std::stod(line.substr(k + 1), &used);
    }
  }
  return last;
}

struct Readback {
  std::optional<ReadError> error;
  std::size_t moves = 0;
  AxisVector position{};
};

Readback read_back(std::string_view program, Dialect dialect, MachineKind kind) {
  Readback out;
  ReadOptions options;
  options.dialect = dialect;
  options.kind = kind;
  const auto result = domain::machine_time::read_program(program, options, [&out](const Move& m) {
    if (m.kind == MoveKind::rapid || m.kind == MoveKind::line || m.kind == MoveKind::arc) {
      ++out.moves;
    }
    out.position = m.end;
  });
  if (const auto* error = std::get_if<ReadError>(&result)) out.error = *error;
  return out;
}

// One program: it reads, moves, and ends at its last words.
void expect_reads_back(std::string_view program, const json& request,
                       const api::CalculationRoute& route, const std::string& label) {
  const json options = request.value("program", json::object());
  const Dialect dialect = dialect_of(options.value("dialect", std::string("linuxcnc")));
  const bool lathe = route.program->machine == MachineKind::lathe;
  const Readback back = read_back(program, dialect, lathe ? MachineKind::lathe : MachineKind::mill);
  ASSERT_FALSE(back.error.has_value())
      << label << ": line " << back.error->line << " column " << back.error->column << " word '"
      << back.error->word << "'";
  EXPECT_GT(back.moves, 0U) << label;
  const double scale = options.value("units", std::string("mm")) == "inch" ? 25.4 : 1.0;
  const LastWords last = last_words(program, dialect);
  constexpr std::array<Axis, 4> kAxes = {Axis::x, Axis::y, Axis::z, Axis::c};
  for (std::size_t k = 0; k < kAxes.size(); ++k) {
    const double got = back.position[domain::machine_time::index(kAxes[k])];
    if (!last.value[k]) {
      EXPECT_EQ(got, 0.0) << label << " axis "
                          << "XYZC"[k];
      continue;
    }
    double want = *last.value[k];
    if (kAxes[k] != Axis::c) want *= scale;
    if (kAxes[k] == Axis::x && lathe) want /= 2.0;  // every lathe program writes diameters
    EXPECT_NEAR(got, want, 1e-9 * std::max(1.0, std::fabs(want))) << label << " axis "
                                                                  << "XYZC"[k];
  }
}

// The program texts of one request's answer, or none when the handler refuses it.
std::vector<std::string> programs_of(const api::CalculationRoute& route, const json& request) {
  api::HandlerOutcome outcome = route.handler(request);
  auto* both = std::get_if<api::JsonWithText>(&outcome);
  if (both != nullptr) api::write_whole(*both);
  if (both == nullptr) return {};
  std::vector<std::string> programs = {both->text};
  if (both->json.contains("program") && both->json.at("program").is_string()) {
    programs.push_back(both->json.at("program").get<std::string>());
  }
  return programs;
}

TEST(ProgramReadback, EveryProgramOfEveryReferenceRequestReadsInItsDialect) {
  std::size_t programs_read = 0;
  std::size_t dialects_refused = 0;
  for (const api::CalculationRoute& route : api::calculation_routes()) {
    if (route.forms != api::AnswerForms::json_and_plain_text_program) continue;
    for (const std::string_view file : api::reference_files_of(route)) {
      const json document = load_reference(std::string(file));
      for (const json& item : document.at("cases")) {
        if (item.at("expect").at("status") != 200) continue;
        const json& request = item.at("request");
        std::vector<json> variants = {request};
        for (const std::string_view dialect : kDialects) {
          json variant = request;
          if (!variant.contains("program")) variant["program"] = json::object();
          variant["program"]["dialect"] = dialect;
          // The Fanuc program number is Fanuc's alone.
          if (dialect != "fanuc") variant["program"].erase("program_number");
          variants.push_back(variant);
        }
        for (std::size_t v = 0; v < variants.size(); ++v) {
          const std::vector<std::string> programs = programs_of(route, variants[v]);
          if (programs.empty()) {
            EXPECT_NE(v, 0U) << route.path << " " << item.at("id") << ": a 200 case refused";
            ++dialects_refused;
            continue;
          }
          const std::string label = std::string(route.path) + " " +
                                    item.at("id").get<std::string>() + " " +
                                    variants[v].value("program", json::object()).dump();
          for (const std::string& program : programs) {
            expect_reads_back(program, variants[v], route, label);
            ++programs_read;
          }
        }
      }
    }
  }
  // Four endpoints, 51 cases, four requests each: the lathe flat refuses fanuc (lathe-flat.md
  // 6.4), so at least a few refusals and several hundred programs.
  EXPECT_GT(programs_read, 200U);
  EXPECT_GT(dialects_refused, 0U);
}

}  // namespace
}  // namespace cutcalc::testing
