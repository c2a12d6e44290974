#include "api/machine_time/program_time_endpoint.h"

#include <string>
#include <vector>

#include "api/field_reader.h"
#include "api/machine_time/machine_time_json.h"
#include "api/program/machine_reader.h"

namespace cutcalc::api::machine_time {
namespace {

namespace mt = domain::machine_time;
namespace model = domain::program;

std::optional<model::Dialect> dialect_of(const std::optional<std::string>& name) {
  if (!name || *name == "linuxcnc") return model::Dialect::linuxcnc;
  if (*name == "fanuc") return model::Dialect::fanuc;
  if (*name == "sinumerik") return model::Dialect::sinumerik;
  return std::nullopt;
}

}  // namespace

HandlerOutcome handle_program_time(const nlohmann::json& body) {
  std::vector<FieldError> errors;
  ObjectReader in = root_reader(body, errors);
  const std::optional<std::string_view> program = in.optional_string("program");
  if (!in.has("program")) {
    in.add_error("program", ErrorCode::required);
  }
  const auto dialect =
      dialect_of(in.optional_choice("dialect", {"linuxcnc", "fanuc", "sinumerik"}));
  const program::MachineRequest machine = program::read_machine(in, program::MachineUse::timing);
  int profile_points = 0;
  if (in.has("profile_points")) {
    profile_points = static_cast<int>(
        in.required_integer("profile_points", mt::kMinProfilePoints, mt::kMaxProfilePoints)
            .value_or(0));
  }
  in.reject_unknown_fields();
  if (!errors.empty()) {
    return invalid_input(std::move(errors));
  }

  mt::ProgramTimeParams params;
  params.program = *program;
  params.read.dialect = dialect.value_or(model::Dialect::linuxcnc);
  params.read.kind = machine.kind;
  params.read.max_spindle_rpm = machine.limits.max_spindle_rpm.value_or(0.0);
  params.machine = *machine.timing;
  params.profile_points = profile_points;
  const mt::ProgramTimeOutcome outcome = mt::time_program(params);
  if (const auto* refused = std::get_if<mt::ReadError>(&outcome)) {
    return to_problem(*refused, "/program");
  }
  if (const auto* missing = std::get_if<mt::AxisNotDescribed>(&outcome)) {
    return to_problem(*missing);
  }
  return to_json(std::get<mt::ProgramTime>(outcome));
}

}  // namespace cutcalc::api::machine_time
