#include "api/warning_catalogue.h"

#include <array>
#include <cstddef>

namespace cutcalc::api {
namespace {

using domain::program::WarningCode;

struct WarningEntry {
  WarningCode code;
  std::string_view en;
  std::string_view ru;
};

// One row per code, in the list's order (checked at compile time below).
constexpr std::array kWarningCatalogue{
    WarningEntry{WarningCode::spindle_over_limit,
                 "The spindle speed is above the machine’s limit (max_spindle_rpm).",
                 "Частота вращения шпинделя выше предела станка (max_spindle_rpm)."},
    WarningEntry{WarningCode::feed_over_limit,
                 "A programmed feed is above the machine’s limit (max_feed_mm_per_min).",
                 "Запрограммированная подача выше предела станка (max_feed_mm_per_min)."},
    WarningEntry{WarningCode::spindle_speed_rounded,
                 "The spindle speed is rounded: a Fanuc S word takes no decimals.",
                 "Частота вращения округлена: слово S в Fanuc не допускает дробной части."},
    WarningEntry{WarningCode::rounding_exceeds_tolerance,
                 "The program as printed deviates from the exact path by more than the arc-fit "
                 "tolerance: print more decimals.",
                 "Программа в напечатанном виде отклоняется от точной траектории больше допуска "
                 "аппроксимации: выводите больше знаков."},
    WarningEntry{WarningCode::feed_exceeds_block_rate,
                 "The programmed feed is above the block-rate feed limit: the control will starve.",
                 "Запрограммированная подача выше предела по скорости обработки кадров: ЧПУ не "
                 "успеет читать кадры."},
    WarningEntry{WarningCode::phase_not_locked,
                 "G95 does not lock the rotor angle to the path: start with corner 0 pointing −Y.",
                 "G95 не привязывает угол ротора к траектории: начинайте с угла 0, направленного "
                 "в −Y."},
    WarningEntry{WarningCode::spindle_speed_limited,
                 "Constant surface speed reaches the spindle limit above the bottom: the speed is "
                 "clamped there.",
                 "Постоянная скорость резания доходит до предела частоты вращения выше дна: там "
                 "частота ограничена."},
    WarningEntry{WarningCode::shift_outside_paper_range,
                 "The axial shift X2 is outside the paper’s tested 0.3–0.5 mm.",
                 "Осевое смещение X2 вне проверенного в статье диапазона 0,3–0,5 мм."},
    WarningEntry{WarningCode::pattern_not_repeated,
                 "Fewer than 5 revolutions: the pattern does not repeat, so the wall pitch and Rz "
                 "are those of the developed pattern.",
                 "Меньше 5 оборотов: схема не повторяется, шаг и Rz стенки — для установившейся "
                 "схемы."},
    WarningEntry{WarningCode::flatness_over_tolerance,
                 "The flatness error of the given N is above the tolerance.",
                 "Отклонение от плоскостности при заданном N больше допуска."},
    WarningEntry{WarningCode::axis_caps_feed,
                 "Some blocks ask for a feed above what the axes (or the trajectory maximum) allow "
                 "along them: they run slower.",
                 "Некоторые кадры задают подачу выше, чем позволяют оси (или предел траектории) в "
                 "их направлении: они выполняются медленнее."},
    WarningEntry{WarningCode::segment_too_short,
                 "Some segments are too short for their feed at one segment per servo period: "
                 "they run slower.",
                 "Некоторые отрезки слишком коротки для своей подачи при одном отрезке за период "
                 "сервоцикла: они выполняются медленнее."},
    WarningEntry{WarningCode::untimed_stop,
                 "The program stops for the operator or a tool change (M0, M1, M6): these stops "
                 "are not in the time.",
                 "Программа останавливается для оператора или смены инструмента (M0, M1, M6): эти "
                 "остановки во время не входят."},
    WarningEntry{WarningCode::units_assumed,
                 "The program states no units (G20 or G21): it is read in mm.",
                 "Программа не задаёт единицы (G20 или G21): она прочитана в миллиметрах."},
};

constexpr std::array kAllWarningCodes{
#define CUTCALC_PROGRAM_WARNING(name) WarningCode::name,
#include "domain/program/warning_codes.def"
#undef CUTCALC_PROGRAM_WARNING
};

constexpr bool catalogue_follows_the_list() {
  if (kWarningCatalogue.size() != kAllWarningCodes.size()) return false;
  for (std::size_t i = 0; i < kAllWarningCodes.size(); ++i) {
    if (kWarningCatalogue[i].code != kAllWarningCodes[i]) return false;
  }
  return true;
}
static_assert(catalogue_follows_the_list(),
              "kWarningCatalogue needs one row per code of warning_codes.def, in its order");

void add_messages_to_list(nlohmann::json& warnings, Language language) {
  for (auto& warning : warnings) {
    if (!warning.is_object() || !warning.contains("code") || !warning["code"].is_string()) {
      continue;
    }
    if (const auto code = warning_code_named(warning["code"].get_ref<const std::string&>())) {
      warning["message"] = warning_message(*code, language);
    }
  }
}

}  // namespace

std::span<const WarningCode> all_warning_codes() { return kAllWarningCodes; }

std::optional<WarningCode> warning_code_named(std::string_view name) {
  for (const WarningCode code : kAllWarningCodes) {
    if (domain::program::warning_name(code) == name) return code;
  }
  return std::nullopt;
}

std::string_view warning_message(WarningCode code, Language language) {
  const WarningEntry& entry = kWarningCatalogue[static_cast<std::size_t>(code)];
  return language == Language::ru ? entry.ru : entry.en;
}

bool add_warning_messages(nlohmann::json& answer, Language language) {
  if (!answer.is_object()) return false;
  bool found = false;
  // Member objects only: arrays (a velocity profile, a program's blocks) hold no warnings lists
  // and may be long.
  for (auto& [name, member] : answer.items()) {
    if (name == "warnings" && member.is_array()) {
      add_messages_to_list(member, language);
      found = true;
    } else if (member.is_object()) {
      found = add_warning_messages(member, language) || found;
    }
  }
  return found;
}

}  // namespace cutcalc::api
