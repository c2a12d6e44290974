#include "api/error_catalogue.h"

#include <array>
#include <cmath>
#include <iterator>
#include <sstream>

namespace cutcalc::api {
namespace {

// The names and the errors[] flag, from the one list.
constexpr std::string_view kNames[] = {
#define CUTCALC_API_ERROR(name, listed) #name,
#include "api/error_codes.def"
#undef CUTCALC_API_ERROR
};
constexpr bool kListed[] = {
#define CUTCALC_API_ERROR(name, listed) listed,
#include "api/error_codes.def"
#undef CUTCALC_API_ERROR
};

// A code's sentences. The name and the errors[] flag come from the list (api/error_codes.def).
struct Entry {
  ErrorCode code;
  std::string_view en;
  std::string_view ru;
};

// One row per code, in the enum's order (checked at compile time below). {interval} is written
// from the parameters minimum/exclusive_minimum/maximum/exclusive_maximum.
constexpr std::array kCatalogue{
    Entry{ErrorCode::no_contact, "the tool does not reach the workpiece: there is no contact",
          "инструмент не касается заготовки: контакта нет"},
    Entry{ErrorCode::stroke_shorter_than_entry,
          "length_mm is too short: the stroke ends before the cutter is fully engaged",
          "length_mm слишком мала: ход заканчивается раньше, чем фреза полностью врежется"},
    Entry{ErrorCode::entry_arc_wider_than_diameter,
          "the entry arc is wider than its diameter: width_mm > 2 radius_mm",
          "дуга входа шире своего диаметра: width_mm > 2 radius_mm"},
    Entry{ErrorCode::exit_arc_wider_than_diameter,
          "the exit arc is wider than its diameter: width_mm > 2 radius_mm",
          "дуга выхода шире своего диаметра: width_mm > 2 radius_mm"},
    Entry{ErrorCode::exit_width_mismatch,
          "the exit contour must have the same width as the entry contour",
          "контур выхода должен иметь ту же ширину, что и контур входа"},
    Entry{ErrorCode::offset_with_several_passes,
          "a non-zero offset_mm applies only to a single lateral pass",
          "ненулевое offset_mm допускается только при одном поперечном проходе"},
    Entry{ErrorCode::allowance_wider_than_part,
          "the allowance width must not exceed the part width",
          "ширина припуска не должна превышать ширину детали"},
    Entry{ErrorCode::allowance_not_full_width,
          "with several lateral passes the allowance width must equal the part width",
          "при нескольких поперечных проходах ширина припуска должна равняться ширине детали"},
    Entry{ErrorCode::width_of_cut_exceeds_diameter,
          "the width of cut must not exceed the cutter diameter",
          "ширина фрезерования не должна превышать диаметр фрезы"},
    Entry{ErrorCode::entry_feed_exceeds_feed,
          "the entry feed per tooth must not exceed the feed per tooth",
          "подача на зуб при врезании не должна превышать подачу на зуб"},
    Entry{ErrorCode::too_many_lateral_passes,
          "too many lateral passes: at most {maximum} are computed",
          "слишком много поперечных проходов: рассчитывается не более {maximum}"},
    Entry{ErrorCode::too_many_depth_passes, "too many depth passes: at most {maximum} are computed",
          "слишком много проходов по глубине: рассчитывается не более {maximum}"},
    Entry{ErrorCode::contact_angle_outside_arc,
          "the contact angle is outside the engagement arc |rho| <= rho_e",
          "угол контакта вне дуги контакта |rho| <= rho_e"},
    Entry{ErrorCode::target_needs_minor_edge_angle,
          "the target crest height needs a larger minor edge angle (at 0 degrees the crest height "
          "is 0 at every feed)",
          "для заданной высоты неровностей нужен больший вспомогательный угол в плане (при 0° "
          "высота неровностей равна 0 при любой подаче)"},
    Entry{ErrorCode::cutter_not_smaller_than_bore,
          "the cutter radius must be smaller than the bore radius",
          "радиус фрезы должен быть меньше радиуса отверстия"},
    Entry{ErrorCode::bore_feed_too_large,
          "the feed is too large for this cutter and bore: the centre would orbit the bore at "
          "least once per revolution, or successive tooth paths would form no cusp",
          "подача слишком велика для этой фрезы и отверстия: центр фрезы обходил бы отверстие за "
          "один оборот или быстрее, либо следы соседних зубьев не образовали бы гребня"},
    Entry{ErrorCode::tolerance_unreachable,
          "the arc fit needs more than {maximum} biarcs per ellipse arc for this tolerance and "
          "diameter",
          "при этих допуске и диаметре аппроксимация требует более {maximum} биарок на дугу "
          "эллипса"},
    Entry{ErrorCode::program_too_large,
          "the program would have more than {maximum} arc blocks: use a larger step_down_mm, "
          "fewer loops_per_layer or a larger tolerance_mm",
          "программа содержала бы более {maximum} кадров с дугами: увеличьте step_down_mm или "
          "tolerance_mm либо уменьшите loops_per_layer"},
    Entry{ErrorCode::pass_program_too_large, "the program would have more than {maximum} blocks",
          "программа содержала бы более {maximum} кадров"},
    Entry{ErrorCode::word_prints_as_zero,
          "a feed, the spindle speed, its limit or a dwell is too small to print with this many "
          "decimals",
          "подача, частота вращения, её предел или выдержка слишком малы для вывода с таким "
          "числом знаков"},
    Entry{ErrorCode::finish_depth_not_below_depth,
          "the finishing depth of cut must be less than the depth allowance (at least one "
          "roughing level)",
          "глубина чистового прохода должна быть меньше припуска по глубине (хотя бы один "
          "черновой проход)"},
    Entry{ErrorCode::target_cusp_unreachable,
          "the target cusp height is not reached: the largest feed the model accepts for this bore "
          "and cutter leaves {maximum} um",
          "заданная высота гребня не достигается: наибольшая допустимая для модели подача при этих "
          "отверстии и фрезе оставляет {maximum} мкм"},
    Entry{ErrorCode::bottom_not_below_start, "the bottom diameter must be below the start diameter",
          "диаметр дна канавки должен быть меньше начального диаметра"},
    Entry{ErrorCode::groove_too_deep,
          "the groove depth must be less than the start radius (2 groove_depth_mm < "
          "start_diameter_mm)",
          "глубина канавки должна быть меньше начального радиуса (2 groove_depth_mm < "
          "start_diameter_mm)"},
    Entry{ErrorCode::shift_too_wide, "the shift must be narrower than the groove",
          "смещение должно быть меньше ширины канавки"},
    Entry{ErrorCode::tool_too_wide, "the tool must be narrower than the groove",
          "резец должен быть уже канавки"},
    Entry{ErrorCode::tool_and_shift_mismatch,
          "tool_width_mm + shift_mm must equal groove_width_mm: give one of them or both matching",
          "tool_width_mm + shift_mm должно равняться groove_width_mm: задайте одно из них или оба "
          "согласованно"},
    Entry{ErrorCode::tool_not_wider_than_shift,
          "the tool must be wider than the shift (tool_width_mm > shift_mm): a narrower tool "
          "leaves a ridge in the groove bottom",
          "резец должен быть шире смещения (tool_width_mm > shift_mm): более узкий резец оставит "
          "гребень на дне канавки"},
    Entry{ErrorCode::too_many_revolutions,
          "the cycle would take more than {maximum} revolutions (one program block each): use a "
          "larger feed_per_rev_mm",
          "цикл занял бы более {maximum} оборотов (по кадру программы на каждый): увеличьте "
          "feed_per_rev_mm"},
    Entry{ErrorCode::flat_outside_part,
          "the flat must lie inside the part: depth and axis distance below the radius, width and "
          "across-flats size below the diameter",
          "лыска должна лежать внутри детали: глубина и расстояние от оси меньше радиуса, ширина и "
          "размер под ключ меньше диаметра"},
    Entry{ErrorCode::tolerance_unmet,
          "no number of steps up to 1000 keeps the flatness within this tolerance",
          "ни одно число шагов до 1000 не обеспечивает эту плоскостность"},
    Entry{ErrorCode::too_many_cut_blocks,
          "the program would have more than {maximum} cutting blocks: use fewer steps, flats or "
          "layers",
          "программа содержала бы более {maximum} рабочих кадров: уменьшите число шагов, лысок "
          "или слоёв"},
    Entry{ErrorCode::flat_too_small,
          "the flat (or a layer of it) is too shallow for this part to be computed: its plane "
          "rounds to the part's surface",
          "лыска (или её слой) слишком мелкая для этой детали: её плоскость при вычислении "
          "совпадает с поверхностью детали"},
    Entry{ErrorCode::steps_below_resolution,
          "a step of the flat moves less than the program prints (its X and C words repeat): use "
          "fewer steps or more decimals",
          "шаг лыски меньше, чем выводит программа (её слова X и C повторяются): уменьшите число "
          "шагов или увеличьте число знаков"},
    Entry{ErrorCode::required, "is required", "обязательное поле"},
    Entry{ErrorCode::required_choice, "is required (one of: {allowed})",
          "обязательное поле (одно из: {allowed})"},
    Entry{ErrorCode::not_a_number, "must be a number", "должно быть числом"},
    Entry{ErrorCode::not_finite, "must be a finite number", "должно быть конечным числом"},
    Entry{ErrorCode::not_an_integer, "must be an integer", "должно быть целым числом"},
    Entry{ErrorCode::must_be_positive, "must be > 0", "должно быть > 0"},
    Entry{ErrorCode::must_not_be_negative, "must be >= 0", "должно быть >= 0"},
    Entry{ErrorCode::below_resolution,
          "must be >= {minimum} (smaller values are below any machine's resolution)",
          "должно быть >= {minimum} (меньшие значения ниже разрешения любого станка)"},
    Entry{ErrorCode::out_of_range, "must be in {interval}", "должно лежать в интервале {interval}"},
    Entry{ErrorCode::wrong_list_length, "must be a list of {min_items} to {max_items} numbers",
          "должно быть списком из {min_items}–{max_items} чисел"},
    Entry{ErrorCode::not_a_boolean, "must be true or false", "должно быть true или false"},
    Entry{ErrorCode::not_a_string, "must be a string", "должно быть строкой"},
    Entry{ErrorCode::not_an_object, "must be an object", "должно быть объектом"},
    Entry{ErrorCode::not_one_of, "must be one of: {allowed}", "должно быть одним из: {allowed}"},
    Entry{ErrorCode::unknown_field, "is not a known field", "неизвестное поле"},
    Entry{ErrorCode::body_not_an_object, "the request body must be a JSON object",
          "тело запроса должно быть объектом JSON"},
    Entry{ErrorCode::exactly_one_field, "give exactly one of {fields}",
          "укажите ровно одно из полей: {fields}"},
    Entry{ErrorCode::exclusive_fields, "give at most one of {fields}",
          "укажите не более одного из полей: {fields}"},
    Entry{ErrorCode::requires_field, "is only used together with {field}",
          "используется только вместе с {field}"},
    Entry{ErrorCode::not_above, "must not be above {field}", "не должно превышать {field}"},
    Entry{ErrorCode::dialect_only, "is for dialect {dialect} only",
          "допускается только в диалекте {dialect}"},
    Entry{ErrorCode::pass_program_only, "is for the pass program (POST /v1/main-time/program) only",
          "допускается только в программе проходов (POST /v1/main-time/program)"},
    Entry{ErrorCode::work_offset_unavailable,
          "is not a work offset of {dialect} (use one of: {allowed})",
          "не является рабочим смещением {dialect} (допустимы: {allowed})"},
    Entry{ErrorCode::invalid_program_name,
          "must be 1 to 24 of A-Z, 0-9 and _, starting with a letter",
          "должно состоять из 1–24 символов A-Z, 0-9 и _ и начинаться с буквы"},
    Entry{ErrorCode::reserved_program_name, "must not be a reserved device name ({name})",
          "не должно быть зарезервированным именем устройства ({name})"},
    Entry{ErrorCode::program_name_two_letters, "must start with two letters (sinumerik)",
          "должно начинаться с двух букв (sinumerik)"},
    Entry{ErrorCode::program_name_reserved_prefix,
          "must not start with {prefix} (reserved by sinumerik)",
          "не должно начинаться с {prefix} (зарезервировано в sinumerik)"},
    Entry{ErrorCode::program_needs_straight_path, "must be 0 (a program needs a straight path)",
          "должно быть 0 (программе нужен прямолинейный путь)"},
    Entry{ErrorCode::dialect_unsupported,
          "this program has no form for this control yet (one of: {allowed})",
          "для этой системы ЧПУ эта программа пока не пишется (одна из: {allowed})"},
    Entry{ErrorCode::at_least_one_field, "give at least one of {fields}",
          "задайте хотя бы одно из {fields}"},
    Entry{ErrorCode::needs_several_flats, "is only defined for two or more flats (flats >= 2)",
          "определено только для двух и более лысок (flats >= 2)"},
    Entry{ErrorCode::gcode_parameter,
          "line {line}, column {column}: {word}: a parameter is known only when the program "
          "runs, so the program cannot be timed",
          "строка {line}, позиция {column}: {word}: значение параметра известно только при "
          "выполнении программы, время не рассчитать"},
    Entry{ErrorCode::gcode_expression,
          "line {line}, column {column}: {word}: expressions cannot be timed",
          "строка {line}, позиция {column}: {word}: выражения не поддерживаются при расчёте "
          "времени"},
    Entry{ErrorCode::gcode_subroutine,
          "line {line}, column {column}: {word}: subroutines, calls and loops cannot be timed",
          "строка {line}, позиция {column}: {word}: подпрограммы, вызовы и циклы не "
          "поддерживаются при расчёте времени"},
    Entry{ErrorCode::gcode_cutter_compensation,
          "line {line}, column {column}: {word}: with cutter compensation on the path depends "
          "on the tool, so it cannot be timed",
          "строка {line}, позиция {column}: {word}: при коррекции на радиус путь зависит от "
          "инструмента, время не рассчитать"},
    Entry{ErrorCode::gcode_canned_cycle,
          "line {line}, column {column}: {word}: canned cycles cannot be timed",
          "строка {line}, позиция {column}: {word}: постоянные циклы не поддерживаются при "
          "расчёте времени"},
    Entry{ErrorCode::gcode_unsupported_word,
          "line {line}, column {column}: {word} is not a word the program reader knows",
          "строка {line}, позиция {column}: слово {word} не поддерживается"},
    Entry{ErrorCode::gcode_malformed, "line {line}, column {column}: {word} is not a valid word",
          "строка {line}, позиция {column}: {word} — некорректное слово"},
    Entry{ErrorCode::gcode_arc_geometry,
          "line {line}, column {column}: {word}: the arc's end point is not on its circle",
          "строка {line}, позиция {column}: {word}: конечная точка дуги не лежит на её "
          "окружности"},
    Entry{ErrorCode::gcode_missing_feed,
          "line {line}, column {column}: {word}: a feed move with no feed in effect (F, or a "
          "turning spindle for feed per revolution)",
          "строка {line}, позиция {column}: {word}: перемещение на подаче без подачи (F или "
          "вращение шпинделя при подаче на оборот)"},
    Entry{ErrorCode::axis_not_described,
          "the program moves axis {axis} (first at line {line}), which the machine does not "
          "describe",
          "программа перемещает ось {axis} (впервые в строке {line}), которой нет в описании "
          "станка"},
    Entry{ErrorCode::empty_body, "the request body is empty; send a JSON object",
          "тело запроса пустое; отправьте объект JSON"},
    Entry{ErrorCode::duplicate_key, "duplicate key \"{key}\" in an object",
          "повторяющийся ключ \"{key}\" в объекте"},
    Entry{ErrorCode::too_deeply_nested, "JSON nested deeper than {levels} levels",
          "JSON вложен глубже {levels} уровней"},
    Entry{ErrorCode::invalid_json, "the request body is not valid JSON: {reason}",
          "тело запроса не является корректным JSON: {reason}"},
    Entry{ErrorCode::unsupported_media_type,
          "send the request body as application/json (got \"{content_type}\")",
          "отправьте тело запроса как application/json (получено \"{content_type}\")"},
    Entry{ErrorCode::no_such_resource, "no such resource: {path}", "нет такого ресурса: {path}"},
    Entry{ErrorCode::method_not_allowed, "{method} is not allowed on {path}; allowed: {allow}",
          "метод {method} не разрешён для {path}; разрешены: {allow}"},
    Entry{ErrorCode::too_many_empty_lines,
          "the HTTP request could not be processed: too many empty lines before the request line",
          "HTTP-запрос не удалось обработать: слишком много пустых строк перед строкой запроса"},
    Entry{ErrorCode::head_too_large,
          "the HTTP request could not be processed: the request head is over the size limit",
          "HTTP-запрос не удалось обработать: заголовок запроса превышает допустимый размер"},
    Entry{ErrorCode::malformed_request_line,
          "the HTTP request could not be processed: malformed request line",
          "HTTP-запрос не удалось обработать: неверная строка запроса"},
    Entry{ErrorCode::request_line_too_large,
          "the HTTP request could not be processed: the request line is over the size limit",
          "HTTP-запрос не удалось обработать: строка запроса превышает допустимый размер"},
    Entry{ErrorCode::unknown_method, "the HTTP request could not be processed: unknown method",
          "HTTP-запрос не удалось обработать: неизвестный метод"},
    Entry{ErrorCode::unsupported_http_version,
          "the HTTP request could not be processed: the HTTP version is not HTTP/1.1 or HTTP/1.0",
          "HTTP-запрос не удалось обработать: версия HTTP — не HTTP/1.1 и не HTTP/1.0"},
    Entry{ErrorCode::malformed_field_line,
          "the HTTP request could not be processed: malformed header field line",
          "HTTP-запрос не удалось обработать: неверная строка поля заголовка"},
    Entry{ErrorCode::field_line_too_large,
          "the HTTP request could not be processed: a header field line is over the size limit",
          "HTTP-запрос не удалось обработать: строка поля заголовка превышает допустимый размер"},
    Entry{ErrorCode::too_many_fields,
          "the HTTP request could not be processed: too many header fields",
          "HTTP-запрос не удалось обработать: слишком много полей заголовка"},
    Entry{
        ErrorCode::malformed_content_length,
        "the HTTP request could not be processed: Content-Length must be one number (digits only)",
        "HTTP-запрос не удалось обработать: Content-Length должен быть одним числом (только "
        "цифры)"},
    Entry{ErrorCode::host_not_once,
          "the HTTP request could not be processed: an HTTP/1.1 request needs exactly one Host "
          "header",
          "HTTP-запрос не удалось обработать: запросу HTTP/1.1 нужно ровно одно поле Host"},
    Entry{ErrorCode::transfer_encoding_and_length,
          "the HTTP request could not be processed: Transfer-Encoding and Content-Length together",
          "HTTP-запрос не удалось обработать: Transfer-Encoding и Content-Length вместе"},
    Entry{ErrorCode::transfer_encoding_in_http_one_zero,
          "the HTTP request could not be processed: Transfer-Encoding in an HTTP/1.0 request",
          "HTTP-запрос не удалось обработать: Transfer-Encoding в запросе HTTP/1.0"},
    Entry{ErrorCode::unsupported_transfer_coding,
          "the HTTP request could not be processed: the only transfer coding accepted is chunked",
          "HTTP-запрос не удалось обработать: принимается только кодирование передачи chunked"},
    Entry{ErrorCode::malformed_chunk_size,
          "the HTTP request could not be processed: malformed chunk size line",
          "HTTP-запрос не удалось обработать: неверная строка размера блока (chunk)"},
    Entry{ErrorCode::chunk_without_crlf,
          "the HTTP request could not be processed: chunk data is not followed by CRLF",
          "HTTP-запрос не удалось обработать: за данными блока (chunk) нет CRLF"},
    Entry{ErrorCode::chunk_framing_too_large,
          "the HTTP request could not be processed: chunk framing is over the head size limit",
          "HTTP-запрос не удалось обработать: разметка блоков (chunk) превышает допустимый размер "
          "заголовка"},
    Entry{ErrorCode::malformed_trailer_field,
          "the HTTP request could not be processed: malformed trailer field",
          "HTTP-запрос не удалось обработать: неверное поле трейлера"},
    Entry{ErrorCode::request_too_large,
          "the HTTP request could not be processed: the request is over the size limit",
          "HTTP-запрос не удалось обработать: запрос превышает допустимый размер"},
    Entry{ErrorCode::body_too_large, "the request body exceeds the size limit",
          "тело запроса превышает допустимый размер"},
    Entry{ErrorCode::shutting_down, "shutting down", "сервис останавливается"},
    Entry{ErrorCode::connection_limit, "the server is at its connection limit; retry later",
          "сервер достиг предела числа соединений; повторите позже"},
    Entry{ErrorCode::calculations_busy,
          "the server is busy with other long calculations; retry after {retry_after_s} s",
          "сервер занят другими долгими расчётами; повторите через {retry_after_s} с"},
    Entry{ErrorCode::uploads_busy,
          "the server is receiving other large programs; retry after {retry_after_s} s",
          "сервер принимает другие большие программы; повторите через {retry_after_s} с"},
    Entry{ErrorCode::calculation_timeout,
          "the calculation took longer than the server allows and was stopped; retry after "
          "{retry_after_s} s",
          "расчёт занял больше времени, чем допускает сервер, и был остановлен; повторите через "
          "{retry_after_s} с"},
    Entry{ErrorCode::memory_busy,
          "the server's memory for requests is taken by other answers and programs; retry after "
          "{retry_after_s} s",
          "память сервера для запросов занята другими ответами и программами; повторите через "
          "{retry_after_s} с"},
    Entry{ErrorCode::internal_error, "an internal error occurred (a bug in cutcalc); it was logged",
          "внутренняя ошибка (ошибка в cutcalc); она записана в журнал"},
};

struct PhraseEntry {
  Phrase phrase;
  std::string_view en;
  std::string_view ru;
};

constexpr std::array kPhrases{
    PhraseEntry{Phrase::field_error, "{field} {message}", "{field}: {message}"},
    PhraseEntry{Phrase::and_n_more, " (and {count} more)", " (и ещё {count})"},
    PhraseEntry{Phrase::invalid_request, "the request is invalid", "запрос некорректен"},
    PhraseEntry{Phrase::title_bad_request, "Bad request", "Некорректный запрос"},
    PhraseEntry{Phrase::title_malformed_json, "Malformed JSON", "Некорректный JSON"},
    PhraseEntry{Phrase::title_payload_too_large, "Payload too large",
                "Слишком большое тело запроса"},
    PhraseEntry{Phrase::title_unsupported_media_type, "Unsupported media type",
                "Неподдерживаемый тип содержимого"},
    PhraseEntry{Phrase::title_invalid_input, "Invalid input", "Недопустимые входные данные"},
    PhraseEntry{Phrase::title_impossible_input, "Input impossible for the model",
                "Входные данные невыполнимы для модели"},
    PhraseEntry{Phrase::title_not_found, "Not found", "Не найдено"},
    PhraseEntry{Phrase::title_method_not_allowed, "Method not allowed", "Метод не разрешён"},
    PhraseEntry{Phrase::title_internal_error, "Internal error", "Внутренняя ошибка"},
    PhraseEntry{Phrase::title_unavailable, "Service unavailable", "Сервис недоступен"},
};

constexpr bool catalogue_in_enum_order() {
  for (std::size_t i = 0; i < kCatalogue.size(); ++i) {
    if (static_cast<std::size_t>(kCatalogue[i].code) != i) return false;
  }
  for (std::size_t i = 0; i < kPhrases.size(); ++i) {
    if (static_cast<std::size_t>(kPhrases[i].phrase) != i) return false;
  }
  return true;
}
static_assert(catalogue_in_enum_order(), "one catalogue row per code, in the enum's order");
static_assert(kCatalogue.size() == std::size(kNames), "one catalogue row per code of the list");

constexpr std::array<ErrorCode, kCatalogue.size()> all_codes() {
  std::array<ErrorCode, kCatalogue.size()> codes{};
  for (std::size_t i = 0; i < kCatalogue.size(); ++i) codes[i] = kCatalogue[i].code;
  return codes;
}
constexpr std::array kAllCodes = all_codes();

// Bounds as people write them: 1e-06, 12, 1e+06.
std::string format_number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string format_value(const nlohmann::json& value) {
  if (value.is_number()) return format_number(value.get<double>());
  if (value.is_string()) return value.get<std::string>();
  if (value.is_array()) {
    std::string joined;
    for (const auto& element : value) {
      if (!joined.empty()) joined += ", ";
      joined += format_value(element);
    }
    return joined;
  }
  return value.dump();
}

// "[3, 12]", "(0, 1e+06]", "(-∞, 5]". Appended piece by piece: GCC 12's -Wrestrict misfires on
// "literal" + std::string.
std::string format_interval(const nlohmann::json& params) {
  std::string out;
  if (params.contains("minimum")) {
    out.append("[").append(format_number(params["minimum"].get<double>()));
  } else if (params.contains("exclusive_minimum")) {
    out.append("(").append(format_number(params["exclusive_minimum"].get<double>()));
  } else {
    out.append("(-∞");
  }
  out.append(", ");
  if (params.contains("maximum")) {
    out.append(format_number(params["maximum"].get<double>())).append("]");
  } else if (params.contains("exclusive_maximum")) {
    out.append(format_number(params["exclusive_maximum"].get<double>())).append(")");
  } else {
    out.append("∞)");
  }
  return out;
}

std::string fill(std::string_view text, const nlohmann::json& params) {
  std::string out;
  out.reserve(text.size() + 16);
  while (!text.empty()) {
    const auto open = text.find('{');
    const auto close = open == std::string_view::npos ? open : text.find('}', open);
    if (close == std::string_view::npos) {
      out += text;
      break;
    }
    out += text.substr(0, open);
    const std::string name(text.substr(open + 1, close - open - 1));
    if (name == "interval") {
      out += format_interval(params);
    } else if (params.is_object() && params.contains(name)) {
      out += format_value(params[name]);
    } else {
      out += text.substr(open, close - open + 1);  // a missing parameter shows as itself
    }
    text.remove_prefix(close + 1);
  }
  return out;
}

}  // namespace

std::string_view language_tag(Language language) { return language == Language::ru ? "ru" : "en"; }

std::span<const ErrorCode> all_error_codes() { return kAllCodes; }

std::string_view code_name(ErrorCode code) { return kNames[static_cast<std::size_t>(code)]; }

bool in_errors_list(ErrorCode code) { return kListed[static_cast<std::size_t>(code)]; }

std::string render_message(ErrorCode code, const nlohmann::json& params, Language language) {
  const Entry& entry = kCatalogue[static_cast<std::size_t>(code)];
  return fill(language == Language::ru ? entry.ru : entry.en, params);
}

std::string render_phrase(Phrase phrase, const nlohmann::json& params, Language language) {
  const PhraseEntry& entry = kPhrases[static_cast<std::size_t>(phrase)];
  return fill(language == Language::ru ? entry.ru : entry.en, params);
}

}  // namespace cutcalc::api
