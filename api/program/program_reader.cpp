#include "api/program/program_reader.h"

#include <string>

namespace cutcalc::api::program {
namespace {

namespace model = domain::program;

// A blending tolerance above this is no longer a tolerance of a machined contour.
constexpr double kMaxPathToleranceMm = 10.0;

void add_name_error(ObjectReader& in, const model::NameProblem& problem) {
  switch (problem.rule) {
    case model::NameRule::shape:
      in.add_error("name", ErrorCode::invalid_program_name);
      return;
    case model::NameRule::reserved_device:
      in.add_error("name", ErrorCode::reserved_program_name, {{"name", problem.subject}});
      return;
    case model::NameRule::sinumerik_two_letters:
      in.add_error("name", ErrorCode::program_name_two_letters);
      return;
    case model::NameRule::sinumerik_reserved_prefix:
      in.add_error("name", ErrorCode::program_name_reserved_prefix, {{"prefix", problem.subject}});
      return;
  }
}

// "G54", ... up to G<last>.
nlohmann::json work_offsets(int last) {
  nlohmann::json offsets = nlohmann::json::array();
  for (int number = 54; number <= last; ++number) {
    std::string offset = "G";  // appended: GCC 12's -Wrestrict misfires on "G" + std::string
    offset += std::to_string(number);
    offsets.push_back(std::move(offset));
  }
  return offsets;
}

model::Dialect read_dialect(ObjectReader& in) {
  const auto dialect = in.optional_choice("dialect", {"linuxcnc", "fanuc", "sinumerik"});
  if (dialect == "fanuc") return model::Dialect::fanuc;
  if (dialect == "sinumerik") return model::Dialect::sinumerik;
  return model::Dialect::linuxcnc;
}

void read_identity(ObjectReader& in, model::ProgramOptions& options) {
  if (in.has("decimals")) {
    options.decimals = static_cast<int>(
        in.required_integer("decimals", model::kMinDecimals, model::kMaxDecimals).value_or(4));
  }
  if (in.has("program_number")) {
    if (options.dialect != model::Dialect::fanuc) {
      in.reject("program_number", ErrorCode::dialect_only, {{"dialect", "fanuc"}});
    } else {
      options.program_number = static_cast<int>(
          in.required_integer("program_number", 1, model::kMaxProgramNumber).value_or(1));
    }
  }
  if (const auto name = in.optional_string("name")) {
    if (const auto problem = model::name_problem(*name, options.dialect)) {
      add_name_error(in, *problem);
    } else {
      options.name = *name;
    }
  }
}

void read_tool_and_machine_state(ObjectReader& in, const ProgramPolicy& policy,
                                 model::ProgramOptions& options) {
  const bool lathe = policy.machine == domain::machine_time::MachineKind::lathe;
  if (in.has("tool_number")) {
    options.tool_number = static_cast<int>(
        in.required_integer("tool_number", 1, lathe ? model::kMaxTurretTool : model::kMaxToolNumber)
            .value_or(1));
  }
  if (!lathe) {
    options.tool_length_offset = in.boolean_or("tool_length_offset", false);
    if (options.tool_length_offset && !in.has("tool_number")) {
      in.add_error("tool_length_offset", ErrorCode::requires_field, {{"field", "tool_number"}});
    }
  }
  if (const auto offset =
          in.optional_choice("work_offset", {"G54", "G55", "G56", "G57", "G58", "G59"})) {
    options.work_offset = std::stoi(offset->substr(1));
    if (options.work_offset > model::max_work_offset(options.dialect)) {
      in.add_error("work_offset", ErrorCode::work_offset_unavailable,
                   {{"dialect", model::dialect_name(options.dialect)},
                    {"allowed", work_offsets(model::max_work_offset(options.dialect))}});
    }
  }
  const auto coolant = in.optional_choice("coolant", {"off", "flood", "mist"});
  options.coolant = coolant == "flood"  ? model::Coolant::flood
                    : coolant == "mist" ? model::Coolant::mist
                                        : model::Coolant::off;
}

void read_motion(ObjectReader& in, const ProgramPolicy& policy, model::ProgramOptions& options) {
  if (policy.motion == MotionMembers::none) return;
  options.safe_z_mm =
      in.number_or("safe_z_mm", Bounds::positive(), policy.safe_z_mm.value_or(options.safe_z_mm));
  if (policy.motion == MotionMembers::safe_z) {
    for (const char* key : {"clearance_mm", "plunge_feed_mm_per_min", "rapid_mm_per_min"}) {
      if (in.has(key)) in.reject(key, ErrorCode::pass_program_only);
    }
    return;
  }
  options.clearance_mm = in.number_or("clearance_mm", Bounds::non_negative(), options.clearance_mm);
  if (options.clearance_mm > options.safe_z_mm) {
    in.add_error("clearance_mm", ErrorCode::not_above, {{"field", "safe_z_mm"}});
  }
  options.plunge_feed_mm_per_min = in.optional_number("plunge_feed_mm_per_min", Bounds::positive());
  options.rapid_mm_per_min =
      in.number_or("rapid_mm_per_min", Bounds::positive(), options.rapid_mm_per_min);
}

// The path control mode (machine-time.md section 7): the tolerance only with blend.
void read_path_control(ObjectReader& program, model::ProgramOptions& options) {
  ObjectReader in = program.object("path_control", false);
  if (!in.present()) return;
  const auto mode = in.required_choice("mode", {"exact_stop", "exact_path", "blend"});
  model::PathControl control;
  control.mode = mode == "exact_stop"   ? model::PathMode::exact_stop
                 : mode == "exact_path" ? model::PathMode::exact_path
                                        : model::PathMode::blend;
  if (in.has("tolerance_mm")) {
    if (control.mode != model::PathMode::blend) {
      in.reject("tolerance_mm", ErrorCode::requires_field, {{"field", "mode: blend"}});
    } else {
      control.tolerance_mm =
          in.optional_number("tolerance_mm", Bounds::positive(kMaxPathToleranceMm));
    }
  }
  in.reject_unknown_fields();
  options.path_control = control;
}

}  // namespace

model::ProgramOptions read_program_options(ObjectReader& root, const ProgramPolicy& policy) {
  ObjectReader in = root.object("program", false);
  model::ProgramOptions options;
  options.dialect = read_dialect(in);
  if (!policy.fanuc && options.dialect == model::Dialect::fanuc) {
    in.add_error("dialect", ErrorCode::dialect_unsupported,
                 {{"allowed", {"linuxcnc", "sinumerik"}}});
  }
  options.units =
      in.optional_choice("units", {"mm", "inch"}) == "inch" ? model::Units::inch : model::Units::mm;
  read_identity(in, options);
  if (policy.tool_and_state) {
    read_tool_and_machine_state(in, policy, options);
  }
  read_motion(in, policy, options);
  read_path_control(in, options);
  in.reject_unknown_fields();
  return options;
}

nlohmann::json to_json(const std::vector<model::Warning>& warnings) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& warning : warnings) {
    list.push_back({{"code", model::warning_name(warning.code)}, {"detail", warning.detail}});
  }
  return list;
}

}  // namespace cutcalc::api::program
