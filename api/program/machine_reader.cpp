#include "api/program/machine_reader.h"

#include <array>
#include <string_view>

namespace cutcalc::api::program {
namespace {

namespace mt = domain::machine_time;

// The servo period a control may have (machine-time.md section 2): 0.1 to 10 ms.
constexpr double kMinServoPeriodMs = 0.1;
constexpr double kMaxServoPeriodMs = 10.0;
constexpr double kDefaultServoPeriodMs = 1.0;

struct AxisFields {
  std::string_view name;
  std::string_view velocity;
  std::string_view acceleration;
};

constexpr std::array<AxisFields, mt::kAxisCount> kAxisFields = {{
    {"x", "max_velocity_mm_per_min", "max_acceleration_mm_per_s2"},
    {"y", "max_velocity_mm_per_min", "max_acceleration_mm_per_s2"},
    {"z", "max_velocity_mm_per_min", "max_acceleration_mm_per_s2"},
    {"a", "max_velocity_deg_per_min", "max_acceleration_deg_per_s2"},
    {"b", "max_velocity_deg_per_min", "max_acceleration_deg_per_s2"},
    {"c", "max_velocity_deg_per_min", "max_acceleration_deg_per_s2"},
}};

}  // namespace

MachineRequest read_machine(ObjectReader& root, MachineUse use) {
  const bool axes_required = use == MachineUse::timing;
  ObjectReader in = root.object("machine", axes_required);
  MachineRequest machine;
  machine.limits.max_spindle_rpm = in.optional_number("max_spindle_rpm", Bounds::positive());
  machine.limits.max_feed_mm_per_min =
      in.optional_number("max_feed_mm_per_min", Bounds::positive());
  if (use == MachineUse::limits_only) {
    // Nothing is written, so nothing is timed (machine-time.md section 2).
    for (const std::string_view key : {"axes", "kind", "servo_period_ms"}) {
      if (in.has(key)) in.reject(key, ErrorCode::pass_program_only);
    }
    in.reject_unknown_fields();
    return machine;
  }
  machine.kind = use == MachineUse::program_lathe ? mt::MachineKind::lathe : mt::MachineKind::mill;
  if (const auto kind = in.optional_choice("kind", {"mill", "lathe"})) {
    machine.kind = *kind == "lathe" ? mt::MachineKind::lathe : mt::MachineKind::mill;
  }
  const double servo_period_ms =
      in.number_or("servo_period_ms", Bounds{kMinServoPeriodMs, true, kMaxServoPeriodMs, true, {}},
                   kDefaultServoPeriodMs);
  ObjectReader axes = in.object("axes", axes_required);
  if (axes.present()) {
    mt::Machine timing;
    for (std::size_t i = 0; i < mt::kAxisCount; ++i) {
      const AxisFields& fields = kAxisFields[i];
      ObjectReader axis = axes.object(fields.name, false);
      if (!axis.present()) continue;
      const auto velocity = axis.required_number(fields.velocity, Bounds::positive());
      const auto acceleration = axis.required_number(fields.acceleration, Bounds::positive());
      axis.reject_unknown_fields();
      if (velocity && acceleration) {
        timing.axes[i] = mt::AxisLimits{*velocity / 60.0, *acceleration};
      }
    }
    axes.reject_unknown_fields();
    if (machine.limits.max_feed_mm_per_min) {
      timing.max_linear_velocity_mm_per_s = *machine.limits.max_feed_mm_per_min / 60.0;
    }
    timing.servo_period_s = servo_period_ms / 1000.0;
    timing.max_spindle_rpm = machine.limits.max_spindle_rpm.value_or(0.0);
    machine.timing = timing;
  } else if (!axes_required) {
    // Without axes nothing is timed: kind and servo_period_ms would be ignored silently.
    for (const std::string_view key : {"kind", "servo_period_ms"}) {
      if (in.has(key)) in.add_error(key, ErrorCode::requires_field, {{"field", "axes"}});
    }
  }
  in.reject_unknown_fields();
  return machine;
}

}  // namespace cutcalc::api::program
