#pragma once
// What each G and M code means in each dialect and on each kind of machine (spec machine-time.md
// sections 4 and 7): one action per code, the modal group it belongs to (two codes of one group in
// a block are refused, as the controls do), or the refusal it earns.

#include <cstdint>

#include "domain/machine_time/gcode_reader.h"

namespace cutcalc::domain::machine_time::detail {

enum class GAction : std::uint8_t {
  rapid,
  line,
  arc_cw,
  arc_ccw,
  cancel_motion,  // G80
  dwell,
  plane_xy,
  plane_xz,
  plane_yz,
  units_inch,           // G20, Sinumerik G700: lengths and feeds
  units_mm,             // G21, Sinumerik G710
  units_inch_geometry,  // Sinumerik G70: lengths only, F stays metric
  units_mm_geometry,    // Sinumerik G71
  absolute,
  incremental,
  arc_centre_absolute,     // LinuxCNC G90.1
  arc_centre_incremental,  // LinuxCNC G91.1
  inverse_time,
  per_minute,
  per_revolution,
  constant_surface_speed,
  constant_rpm,
  spindle_clamp,  // Sinumerik G26 S
  diameter_on,    // LinuxCNC G7
  diameter_off,   // LinuxCNC G8
  exact_stop,
  exact_path,
  blend,
  blend_rounded,     // Sinumerik G641: blend within ADIS
  exact_stop_block,  // Fanuc G09, Sinumerik G9: one block
  set_origin,        // G92; Fanuc lathe G50 (X Z: origin; S: spindle clamp)
  cancel_origin,     // LinuxCNC G92.1
  ignored,           // accepted, no effect on the motion or its time
  canned_cycle,      // refusals from here on
  compensation_on,
  subroutine,
  unsupported,
};

enum class GGroup : std::uint8_t {
  none,
  motion,
  plane,
  units,
  distance,
  arc_distance,
  feed_mode,
  spindle_mode,
  diameter,
  path,
  compensation,
  tool_length,
  work_offset,
  non_modal,  // G4, G92, G92.1, Fanuc lathe G50, Sinumerik G26: one per block
};

struct GMeaning {
  GAction action = GAction::unsupported;
  GGroup group = GGroup::none;
};

// `code`: the G number times 10 (G61.1 -> 611).
GMeaning g_meaning(program::Dialect dialect, MachineKind kind, int code);

enum class MAction : std::uint8_t {
  stop,         // M0, M1: the control waits for the operator
  tool_change,  // M6
  end,          // M2, M30
  spindle_on,   // M3, M4
  spindle_off,  // M5
  ignored,      // coolant
  subroutine,   // M98, M99, Sinumerik M17
  unsupported,
};

enum class MGroup : std::uint8_t { none, stopping, tool_change, spindle, coolant };

struct MMeaning {
  MAction action = MAction::unsupported;
  MGroup group = MGroup::none;
};

MMeaning m_meaning(program::Dialect dialect, int code);

}  // namespace cutcalc::domain::machine_time::detail
