// machine-time.md sections 4 and 7: the G and M codes of LinuxCNC 2.9, Fanuc (0i/30i milling,
// and turning in G-code system A) and Sinumerik 840D sl / 828D that a program can hold, and what
// the reader does with each. A code not listed is refused as unsupported: timing it would be a
// guess.

#include "domain/machine_time/gcode_codes.h"

namespace cutcalc::domain::machine_time::detail {
namespace {

using program::Dialect;

constexpr GMeaning motion(GAction action) { return {action, GGroup::motion}; }
constexpr GMeaning of(GAction action, GGroup group) { return {action, group}; }
constexpr GMeaning refused(GAction action) { return {action, GGroup::none}; }
constexpr GMeaning kIgnored{GAction::ignored, GGroup::none};
constexpr GMeaning kUnsupported{GAction::unsupported, GGroup::none};
constexpr GMeaning kExactStopBlock{GAction::exact_stop_block, GGroup::none};

bool is_drilling_cycle(int code) {
  return code == 730 || code == 740 || code == 760 ||
         (code >= 810 && code <= 890 && code % 10 == 0);
}

// The codes every dialect shares, with the same meaning.
GMeaning common(int code) {
  switch (code) {
    case 0:
      return motion(GAction::rapid);
    case 10:
      return motion(GAction::line);
    case 20:
      return motion(GAction::arc_cw);
    case 30:
      return motion(GAction::arc_ccw);
    case 40:
      return of(GAction::dwell, GGroup::non_modal);
    case 170:
      return of(GAction::plane_xy, GGroup::plane);
    case 180:
      return of(GAction::plane_xz, GGroup::plane);
    case 190:
      return of(GAction::plane_yz, GGroup::plane);
    case 400:
      return of(GAction::ignored, GGroup::compensation);
    case 410:
    case 420:
      return refused(GAction::compensation_on);
    case 490:
      return of(GAction::ignored, GGroup::tool_length);
    case 540:
    case 550:
    case 560:
    case 570:
      return of(GAction::ignored, GGroup::work_offset);  // machine-time.md 4: offsets as 0
    case 640:
      return of(GAction::blend, GGroup::path);
    case 800:
      return motion(GAction::cancel_motion);
    case 960:
      return of(GAction::constant_surface_speed, GGroup::spindle_mode);
    case 970:
      return of(GAction::constant_rpm, GGroup::spindle_mode);
    default:
      break;
  }
  if (is_drilling_cycle(code)) return refused(GAction::canned_cycle);
  return kUnsupported;
}

// G90, G91 and G93-G95 as LinuxCNC, Sinumerik and Fanuc's milling controls read them (a Fanuc
// lathe in G-code system A has other meanings for them), then the common codes.
GMeaning distance_and_feed_modes(int code) {
  switch (code) {
    case 900:
      return of(GAction::absolute, GGroup::distance);
    case 910:
      return of(GAction::incremental, GGroup::distance);
    case 930:
      return of(GAction::inverse_time, GGroup::feed_mode);
    case 940:
      return of(GAction::per_minute, GGroup::feed_mode);
    case 950:
      return of(GAction::per_revolution, GGroup::feed_mode);
    default:
      return common(code);
  }
}

GMeaning linuxcnc(int code) {
  switch (code) {
    case 70:
      return of(GAction::diameter_on, GGroup::diameter);
    case 80:
      return of(GAction::diameter_off, GGroup::diameter);
    case 200:
      return of(GAction::units_inch, GGroup::units);
    case 210:
      return of(GAction::units_mm, GGroup::units);
    case 411:
    case 421:
      return refused(GAction::compensation_on);
    case 430:
      return of(GAction::ignored, GGroup::tool_length);
    case 580:
    case 590:
    case 591:
    case 592:
    case 593:
      return of(GAction::ignored, GGroup::work_offset);  // machine-time.md 4: offsets as 0
    case 610:
      return of(GAction::exact_path, GGroup::path);
    case 611:
      return of(GAction::exact_stop, GGroup::path);
    case 700:  // lathe finishing and roughing cycles of 2.9
    case 710:
    case 711:
    case 712:
    case 720:
    case 721:
    case 722:
      return refused(GAction::canned_cycle);
    case 901:
      return of(GAction::arc_centre_absolute, GGroup::arc_distance);
    case 911:
      return of(GAction::arc_centre_incremental, GGroup::arc_distance);
    case 920:
      return of(GAction::set_origin, GGroup::non_modal);
    case 921:
      return of(GAction::cancel_origin, GGroup::non_modal);
    case 980:  // canned cycle return level: no cycle runs
    case 990:
      return kIgnored;
    default:
      return distance_and_feed_modes(code);
  }
}

GMeaning fanuc(MachineKind kind, int code) {
  const bool lathe = kind == MachineKind::lathe;
  switch (code) {
    case 90:
      return kExactStopBlock;
    case 200:
      return of(GAction::units_inch, GGroup::units);
    case 210:
      return of(GAction::units_mm, GGroup::units);
    case 430:
    case 440:
      return of(GAction::ignored, GGroup::tool_length);
    case 150:  // polar coordinates off
    case 670:  // modal macro call off
    case 690:  // coordinate rotation off
    case 501:  // programmable mirror image off
    case 131:  // polar coordinate interpolation off
      return kIgnored;
    case 500:  // lathe: spindle clamp or coordinate setting; mill: scaling off
      return lathe ? of(GAction::set_origin, GGroup::non_modal) : kIgnored;
    case 541:
    case 580:
    case 590:
      return of(GAction::ignored, GGroup::work_offset);  // machine-time.md 4: offsets as 0
    // machine-time.md 7: Fanuc has no exact path mode of its own; G61 is its exact stop mode.
    case 610:
      return of(GAction::exact_stop, GGroup::path);
    case 650:
    case 660:
      return refused(GAction::subroutine);
    default:
      break;
  }
  if (lathe) {
    // G-code system A (grooving-cycle.md 5.2): G90/G92/G94 and G70-G76 are turning cycles,
    // G98/G99 the feed modes; there is no G91 (U and W are the incremental addresses).
    if ((code >= 700 && code <= 760 && code % 10 == 0) || code == 900 || code == 920 ||
        code == 940) {
      return refused(GAction::canned_cycle);
    }
    if (code == 980) return of(GAction::per_minute, GGroup::feed_mode);
    if (code == 990) return of(GAction::per_revolution, GGroup::feed_mode);
    return common(code);
  }
  switch (code) {
    case 920:
      return of(GAction::set_origin, GGroup::non_modal);
    case 980:  // canned cycle return level: no cycle runs
    case 990:
      return kIgnored;
    default:
      return distance_and_feed_modes(code);
  }
}

GMeaning sinumerik(int code) {
  switch (code) {
    case 90:
      return kExactStopBlock;
    case 260:
      return of(GAction::spindle_clamp, GGroup::non_modal);
    case 700:
      return of(GAction::units_inch_geometry, GGroup::units);
    case 710:
      return of(GAction::units_mm_geometry, GGroup::units);
    case 7000:
      return of(GAction::units_inch, GGroup::units);
    case 7100:
      return of(GAction::units_mm, GGroup::units);
    case 5000:                                           // G500: settable work offsets off
      return of(GAction::ignored, GGroup::work_offset);  // machine-time.md 4: offsets as 0
    case 600:
      return of(GAction::exact_stop, GGroup::path);
    case 6010:  // G601-G603, exact stop windows: the stop itself is what the planner models
    case 6020:
    case 6030:
      return kIgnored;
    case 6410:
      return of(GAction::blend_rounded, GGroup::path);
    case 4500:  // corner behaviour of cutter compensation, which is off
    case 4510:
      return kIgnored;
    default:
      break;
  }
  // G505-G599: further settable work offsets.
  if (code >= 5050 && code <= 5990 && code % 10 == 0) {
    return of(GAction::ignored, GGroup::work_offset);
  }
  return distance_and_feed_modes(code);
}

}  // namespace

GMeaning g_meaning(program::Dialect dialect, MachineKind kind, int code) {
  switch (dialect) {
    case Dialect::fanuc:
      return fanuc(kind, code);
    case Dialect::sinumerik:
      return sinumerik(code);
    case Dialect::linuxcnc:
      break;
  }
  return linuxcnc(code);
}

MMeaning m_meaning(program::Dialect dialect, int code) {
  switch (code) {
    case 0:
    case 10:
      return {MAction::stop, MGroup::stopping};
    case 20:
    case 300:
      return {MAction::end, MGroup::stopping};
    case 30:
    case 40:
      return {MAction::spindle_on, MGroup::spindle};
    case 50:
      return {MAction::spindle_off, MGroup::spindle};
    case 60:
      return {MAction::tool_change, MGroup::tool_change};
    case 70:
    case 80:
    case 90:
      return {MAction::ignored, MGroup::coolant};
    case 980:
    case 990:
      return {MAction::subroutine, MGroup::stopping};
    case 170:
      return dialect == program::Dialect::sinumerik
                 ? MMeaning{MAction::subroutine, MGroup::stopping}
                 : MMeaning{};
    default:
      return {};
  }
}

}  // namespace cutcalc::domain::machine_time::detail
