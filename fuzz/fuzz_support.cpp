#include "fuzz/fuzz_support.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <unordered_set>
#include <vector>

#include "api/json_endpoint.h"
#include "api/problem.h"
#include "api/routes.h"
#include "support/quantity_keys.h"

#ifdef CUTCALC_FUZZ_OPENAPI_PATH
#include "support/openapi_contract.h"
#endif

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);

namespace cutcalc::fuzz {
namespace {

// The statuses a calculation endpoint may answer (openapi.yaml); 500 is always a bug.
constexpr std::array kPromisedStatuses = {200, 400, 413, 415, 422};

api::JsonHandler handler_for(std::string_view path) {
  for (const api::CalculationRoute& route : api::calculation_routes()) {
    if (path == route.path) {
      return route.handler;
    }
  }
  std::fprintf(stderr, "fuzz: no calculation route %.*s\n", static_cast<int>(path.size()),
               path.data());
  std::abort();
}

// Whether the route's answers carry a program (its row has the text/plain form; the JSON form
// has it as `program`).
bool writes_program(std::string_view path) {
  const api::CalculationRoute* route = api::find_calculation_route(path);
  return route != nullptr && route->forms == api::AnswerForms::json_and_plain_text_program;
}

// A program a route wrote: today's polygon program, or a program in a dialect (every other
// writer, and the polygon's with a `program` object).
std::optional<std::string> bad_written_program(std::string_view program) {
  return program.starts_with("%\n(CUTCALC POLYGON HOLE N") ? bad_program_text(program)
                                                           : bad_dialect_program_text(program);
}

#ifdef CUTCALC_FUZZ_OPENAPI_PATH
const test_support::OpenApiContract& contract() {
  static const test_support::OpenApiContract loaded =
      test_support::OpenApiContract::load(CUTCALC_FUZZ_OPENAPI_PATH);
  return loaded;
}

std::optional<std::string> joined(const char* what, const std::vector<std::string>& violations) {
  if (violations.empty()) {
    return std::nullopt;
  }
  std::string out = what;
  for (std::size_t i = 0; i < violations.size() && i < 5; ++i) {
    out += "\n  " + violations[i];
  }
  return out;
}

// openapi.yaml: the response matches its documented schema; a request answered 200 is valid.
std::optional<std::string> contract_violation(std::string_view path, std::string_view request_body,
                                              const api::ApiResponse& response,
                                              const nlohmann::json& body) {
  const std::string route(path);
  std::optional<std::string> why;
  if (response.status != 200) {
    // problem_shape has checked every error entry, pointers (RFC 6901) included. What the schema
    // adds depends only on the skeleton: type, title, status, instance, and whether there are
    // entries; the detail texts and pointers are free strings to it. So the schema checks each
    // skeleton once (it compiles its regular expressions on every call: milliseconds under ASan).
    nlohmann::json skeleton = body;
    skeleton.erase("request_id");  // always "fuzz"
    skeleton["detail"] = "x";
    auto& errors = skeleton["errors"];
    if (errors.size() > 1) {
      errors.erase(errors.begin() + 1, errors.end());
    }
    for (auto& error : errors) {
      error["pointer"] = "";
      error["detail"] = "x";
    }
    static std::unordered_set<std::string> conforming;
    std::string key = route + " " + skeleton.dump();
    if (conforming.count(key) != 0) {
      return std::nullopt;
    }
    why = joined(
        "the response does not conform to openapi.yaml:",
        contract().check_response("POST", route, response.status, response.content_type, skeleton));
    if (!why) {
      conforming.insert(std::move(key));
    }
  } else {
    why = joined(
        "the response does not conform to openapi.yaml:",
        contract().check_response("POST", route, response.status, response.content_type, body));
  }
  if (why) {
    return why;
  }
  if (response.status == 200) {
    const auto request = nlohmann::json::parse(request_body, nullptr, false);
    if (request.is_discarded()) {
      return std::string("a 200 answer to a body that does not parse as JSON");
    }
    return joined("the service answered 200 to a request that openapi.yaml refuses:",
                  contract().check_request("POST", route, request));
  }
  return std::nullopt;
}
#endif

bool starts_with(std::string_view text, std::string_view prefix) {
  return text.substr(0, prefix.size()) == prefix;
}

bool ends_with(std::string_view text, std::string_view suffix) {
  return text.size() >= suffix.size() && text.substr(text.size() - suffix.size()) == suffix;
}

std::string escape_pointer_token(const std::string& key) {
  std::string out;
  for (const char c : key) {
    out += c == '~' ? std::string("~0") : c == '/' ? std::string("~1") : std::string(1, c);
  }
  return out;
}

std::optional<std::string> first_negative(const nlohmann::json& value, const std::string& pointer,
                                          bool non_negative) {
  if (value.is_number() && non_negative && value.get<double>() < 0.0) {
    return pointer + " = " + value.dump();
  }
  if (value.is_object()) {
    for (const auto& [key, element] : value.items()) {
      if (auto found = first_negative(element, pointer + "/" + escape_pointer_token(key),
                                      is_non_negative_key(key))) {
        return found;
      }
    }
  }
  if (value.is_array()) {
    std::size_t index = 0;
    for (const auto& element : value) {
      // A list under a length key (depth_passes_mm) holds lengths.
      if (auto found =
              first_negative(element, pointer + "/" + std::to_string(index++), non_negative)) {
        return found;
      }
    }
  }
  return std::nullopt;
}

// A word of the program: G and M take a whole number, every other letter a real number with four
// decimals (openapi.yaml, GcodeProgramText).
bool is_gcode_value(char letter, std::string_view text) {
  const auto all_digits = [](std::string_view part) {
    return !part.empty() && std::all_of(part.begin(), part.end(), [](char c) {
      return std::isdigit(static_cast<unsigned char>(c)) != 0;
    });
  };
  if (letter == 'G' || letter == 'M') {
    return all_digits(text);
  }
  if (starts_with(text, "-")) {
    text.remove_prefix(1);
  }
  const auto dot = text.find('.');
  return dot != std::string_view::npos && all_digits(text.substr(0, dot)) &&
         text.size() - dot - 1 == 4 && all_digits(text.substr(dot + 1));
}

bool is_non_finite_word(std::string_view word) {
  std::string lower(word);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (starts_with(lower, "-") || starts_with(lower, "+")) {
    lower.erase(0, 1);
  }
  return lower == "nan" || lower == "inf" || lower == "infinity";
}

// RFC 6901: "" or "/token..." where '~' is only ever followed by 0 or 1.
bool is_json_pointer(std::string_view pointer) {
  if (!pointer.empty() && pointer.front() != '/') {
    return false;
  }
  for (std::size_t i = 0; i < pointer.size(); ++i) {
    if (pointer[i] == '~' &&
        (i + 1 == pointer.size() || (pointer[i + 1] != '0' && pointer[i + 1] != '1'))) {
      return false;
    }
  }
  return true;
}

std::optional<std::string> problem_shape(const nlohmann::json& body, int status) {
  if (!body.contains("status") || body["status"] != status) {
    return "the problem's status member differs from the HTTP status";
  }
  if (!body.contains("type") || !body["type"].is_string() ||
      !starts_with(body["type"].get_ref<const std::string&>(), "urn:cutcalc:problem:")) {
    return "the problem has no urn:cutcalc:problem: type";
  }
  if (!body.contains("title") || !body["title"].is_string() || !body.contains("detail") ||
      !body["detail"].is_string()) {
    return "the problem has no title or detail";
  }
  if (!body.contains("errors") || !body["errors"].is_array()) {
    return "the problem has no errors list";
  }
  for (const auto& error : body["errors"]) {
    if (!error.is_object() || !error.contains("pointer") || !error["pointer"].is_string() ||
        !error.contains("detail") || !error["detail"].is_string()) {
      return "an entry of errors has no string pointer and detail";
    }
    if (!is_json_pointer(error["pointer"].get_ref<const std::string&>())) {
      return "an error pointer is not a JSON Pointer (RFC 6901): " + error["pointer"].dump();
    }
  }
  if (status == 422 && body["errors"].empty()) {
    return "a 422 problem without any entry in errors (openapi.yaml: minItems 1)";
  }
  return std::nullopt;
}

void report_and_abort(const std::string& why, const api::ApiResponse& response,
                      std::string_view input) {
  std::fprintf(stderr,
               "\n=== cutcalc fuzz: broken promise: %s\n=== status %d, content type %s\n"
               "=== response body (first 2000 bytes):\n%.*s\n=== request body (first 2000 "
               "bytes):\n%.*s\n",
               why.c_str(), response.status, response.content_type.c_str(),
               static_cast<int>(std::min<std::size_t>(response.body.size(), 2000)),
               response.body.data(), static_cast<int>(std::min<std::size_t>(input.size(), 2000)),
               input.data());
  std::abort();
}

// --- the structural JSON mutator

using Rng = std::minstd_rand;

std::size_t pick(Rng& rng, std::size_t count) { return static_cast<std::size_t>(rng()) % count; }

// Numbers where the validation and the formulas change behaviour: zero and its sign, the
// smallest accepted positive value and the largest accepted length (api/field_reader.h) with
// their neighbours, angles, and the extremes of double.
double edge_double(Rng& rng) {
  static constexpr std::array kEdges = {0.0,
                                        -0.0,
                                        1.0,
                                        -1.0,
                                        0.5,
                                        2.0,
                                        1e-6,
                                        9.999999999999999e-7,
                                        1.0000000000000002e-6,
                                        1e-7,
                                        1e-3,
                                        1e6,
                                        999999.9999999999,
                                        1000000.0000000001,
                                        1e7,
                                        45.0,
                                        90.0,
                                        89.99999999999999,
                                        180.0,
                                        360.0,
                                        -90.0,
                                        1e-300,
                                        5e-324,
                                        2.2250738585072014e-308,
                                        1e300,
                                        1.7976931348623157e308,
                                        -1.7976931348623157e308};
  return kEdges[pick(rng, kEdges.size())];
}

double tweak(double x, Rng& rng) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  switch (pick(rng, 9)) {
    case 0:
      return -x;
    case 1:
      return x * 10.0;
    case 2:
      return x / 10.0;
    case 3:
      return std::nextafter(x, kInfinity);
    case 4:
      return std::nextafter(x, -kInfinity);
    case 5:
      return x + 1.0;
    case 6:
      return x - 1.0;
    case 7:
      return x * std::uniform_real_distribution<double>(0.5, 1.5)(rng);
    default:
      return std::uniform_real_distribution<double>(-2.0 * std::abs(x) - 1.0,
                                                    2.0 * std::abs(x) + 1.0)(rng);
  }
}

void mutate_number(nlohmann::json& value, Rng& rng) {
  if (value.is_number_integer() && pick(rng, 4) != 0) {
    static constexpr std::array<std::int64_t, 14> kIntegers = {
        0, 1, 2, 3, 4, 5, 11, 12, 13, 100, 101, -1, 2147483648, 9007199254740993};
    const auto n = value.get<std::int64_t>();
    switch (pick(rng, 3)) {
      case 0:
        value = kIntegers[pick(rng, kIntegers.size())];
        return;
      case 1:
        value = n + (pick(rng, 2) == 0 ? 1 : -1);
        return;
      default:
        value = static_cast<double>(n) + 0.5;
        return;
    }
  }
  const double x = value.get<double>();
  double next = pick(rng, 3) == 0 ? edge_double(rng) : tweak(x, rng);
  if (!std::isfinite(next)) {
    next = edge_double(rng);
  }
  value = next;
}

// Every node of the document, parents before children.
void collect(nlohmann::json& value, std::vector<nlohmann::json*>& nodes) {
  nodes.push_back(&value);
  if (value.is_structured()) {
    for (auto& element : value) {
      collect(element, nodes);
    }
  }
}

void collect_keys(const nlohmann::json& value, std::vector<std::string>& keys) {
  if (value.is_object()) {
    for (const auto& [key, element] : value.items()) {
      keys.push_back(key);
      collect_keys(element, keys);
    }
  } else if (value.is_array()) {
    for (const auto& element : value) {
      collect_keys(element, keys);
    }
  }
}

template <typename Predicate>
nlohmann::json* pick_node(std::vector<nlohmann::json*>& nodes, Rng& rng, Predicate matches) {
  std::vector<nlohmann::json*> candidates;
  for (nlohmann::json* node : nodes) {
    if (matches(*node)) {
      candidates.push_back(node);
    }
  }
  return candidates.empty() ? nullptr : candidates[pick(rng, candidates.size())];
}

// One structural mutation; false when the document offers nothing for the chosen kind.
bool mutate_document(nlohmann::json& document, Rng& rng) {
  std::vector<nlohmann::json*> nodes;
  collect(document, nodes);
  const std::size_t kind = pick(rng, 10);
  if (kind < 5) {  // numbers are what the fields mostly are
    nlohmann::json* number =
        pick_node(nodes, rng, [](const nlohmann::json& v) { return v.is_number(); });
    if (number == nullptr) {
      return false;
    }
    mutate_number(*number, rng);
    return true;
  }
  if (kind == 5) {  // another choice of the API (contours, milling sense, synchronisation)
    static constexpr std::array<const char*, 11> kChoices = {
        "straight", "convex_arc", "concave_arc",  "wall",     "up", "down",
        "climb",    "c_axis",     "feed_per_rev", "STRAIGHT", ""};
    nlohmann::json* text =
        pick_node(nodes, rng, [](const nlohmann::json& v) { return v.is_string(); });
    if (text == nullptr) {
      return false;
    }
    *text = kChoices[pick(rng, kChoices.size())];
    return true;
  }
  if (kind == 6) {  // remove a member or an element
    nlohmann::json* container = pick_node(
        nodes, rng, [](const nlohmann::json& v) { return v.is_structured() && !v.empty(); });
    if (container == nullptr) {
      return false;
    }
    auto position = container->begin();
    std::advance(position, static_cast<std::ptrdiff_t>(pick(rng, container->size())));
    container->erase(position);
    return true;
  }
  if (kind == 7) {  // copy a value under a key of the document into an object (or an array)
    std::vector<std::string> keys;
    collect_keys(document, keys);
    nlohmann::json* source = nodes[pick(rng, nodes.size())];
    nlohmann::json* target =
        pick_node(nodes, rng, [](const nlohmann::json& v) { return v.is_structured(); });
    if (target == nullptr || (keys.empty() && target->is_object())) {
      return false;
    }
    const nlohmann::json copy = *source;
    if (target->is_object()) {
      (*target)[keys[pick(rng, keys.size())]] = copy;
    } else {
      target->push_back(copy);
    }
    return true;
  }
  // another JSON type in place of a value
  nlohmann::json* value = nodes[pick(rng, nodes.size())];
  switch (pick(rng, 7)) {
    case 0:
      *value = nullptr;
      break;
    case 1:
      *value = pick(rng, 2) == 0;
      break;
    case 2:
      *value = value->is_number() ? nlohmann::json(value->dump()) : nlohmann::json("1");
      break;
    case 3:
      *value = nlohmann::json::array({*value});
      break;
    case 4:
      *value = nlohmann::json::object();
      break;
    case 5:
      *value = nlohmann::json::array();
      break;
    default:
      *value = edge_double(rng);
      break;
  }
  return true;
}
}  // namespace

bool is_non_negative_key(std::string_view key) {
  return test_support::is_non_negative_quantity(key);
}

std::optional<std::string> negative_length(const nlohmann::json& body) {
  return first_negative(body, "", false);
}

namespace {

// A program is printable US-ASCII lines, each ended by LF.
std::optional<std::string> bad_ascii_lines(std::string_view program) {
  if (program.empty() || program.back() != '\n') {
    return "the program is empty or does not end with a newline";
  }
  for (const char c : program) {
    const auto byte = static_cast<unsigned char>(c);
    if (c != '\n' && (byte < 0x20 || byte > 0x7e)) {
      return "the program has a byte outside printable US-ASCII: " + std::to_string(byte);
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> bad_program_text(std::string_view program) {
  if (auto why = bad_ascii_lines(program)) {
    return why;
  }
  std::size_t line_number = 0;
  std::size_t begin = 0;
  while (begin < program.size()) {
    const std::size_t end = program.find('\n', begin);
    const std::string_view line = program.substr(begin, end - begin);
    begin = end + 1;
    ++line_number;
    const std::string where =
        "line " + std::to_string(line_number) + " \"" + std::string(line.substr(0, 200)) + "\": ";
    if (line == "%") {
      continue;
    }
    if (starts_with(line, "(")) {
      // A whole-line comment: closed at the end of the line, nothing nested, no NaN printed in it.
      if (!ends_with(line, ")") || line.size() < 2 ||
          line.substr(1, line.size() - 2).find_first_of("()") != std::string_view::npos) {
        return where + "a comment that is not one closed (...) per line";
      }
      std::size_t word_begin = 1;
      while (word_begin < line.size() - 1) {
        std::size_t word_end = line.find_first_of(" )", word_begin);
        const std::string_view word = line.substr(word_begin, word_end - word_begin);
        if (is_non_finite_word(word)) {
          return where + "a non-finite number in a comment";
        }
        word_begin = word_end + 1;
      }
      continue;
    }
    if (line.empty()) {
      return where + "an empty line";
    }
    // Code: words "<letter><value>" separated by single spaces, letters in the order G X Y Z I J C
    // F S M (so never an R arc).
    constexpr std::string_view kOrder = "GXYZIJCFSM";
    std::size_t previous_rank = 0;
    std::size_t word_begin = 0;
    while (word_begin <= line.size()) {
      std::size_t word_end = line.find(' ', word_begin);
      if (word_end == std::string_view::npos) {
        word_end = line.size();
      }
      const std::string_view word = line.substr(word_begin, word_end - word_begin);
      const std::size_t rank = word.empty() ? std::string_view::npos : kOrder.find(word.front());
      if (rank == std::string_view::npos || !is_gcode_value(word.front(), word.substr(1))) {
        return where + "a word that is not one of G X Y Z I J C F S M with a finite number: \"" +
               std::string(word) + "\"";
      }
      if (rank < previous_rank) {
        return where + "words out of the order G X Y Z I J C F S M";
      }
      previous_rank = rank;
      word_begin = word_end + 1;
    }
  }
  if (!starts_with(program, "%\n") || !ends_with(program, "\n%\n")) {
    return "the program is not enclosed in % lines";
  }
  return std::nullopt;
}

// The words of a block (split at single spaces; an empty word stays, and is refused).
std::vector<std::string_view> block_words(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t begin = 0;
  while (begin <= line.size()) {
    std::size_t end = line.find(' ', begin);
    if (end == std::string_view::npos) end = line.size();
    words.push_back(line.substr(begin, end - begin));
    begin = end + 1;
  }
  return words;
}

bool is_whole(std::string_view text) {
  return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
  });
}

// A real number with its decimal point, never -0.
bool is_real(std::string_view text) {
  const bool negative = starts_with(text, "-");
  if (negative) text.remove_prefix(1);
  const auto dot = text.find('.');
  if (dot == std::string_view::npos || !is_whole(text.substr(0, dot)) ||
      !is_whole(text.substr(dot + 1))) {
    return false;
  }
  return !negative || text.find_first_not_of("0.") != std::string_view::npos;
}

// A real number (whole for fanuc S) that does not print as zero: F, S, D/LIMS/G50, dwell
// seconds (grooving-cycle.md 5.1: such a program is a 422, never a 200).
bool is_positive_value(std::string_view text, bool whole) {
  return (whole ? is_whole(text) : is_real(text) && !starts_with(text, "-")) &&
         text.find_first_not_of("0.") != std::string_view::npos;
}

// A lathe block (grooving-cycle.md section 5.2, the writer of domain/program/lathe_program.h)
// that is not one of the dialect's literal forms; nullopt when it is. The tool call, spindle
// and dwell blocks are checked whole; every other block has the words G X Z C F S M in that order
// (G and M whole numbers, X Z C F real, no Y I J H T D P), sinumerik's modal DIAMON among the
// G words, one M word. Where a C word may stand is bad_flat_block's (lathe-flat.md 6.2).
std::optional<std::string> bad_lathe_block(std::string_view line, bool fanuc, bool sinumerik) {
  const std::vector<std::string_view> w = block_words(line);
  const auto value = [](std::string_view word) { return word.substr(1); };
  const auto tool = [&](std::string_view word) {
    return word.size() >= 2 && word[0] == 'T' && is_whole(value(word)) &&
           std::stoi(std::string(value(word))) >= 1 && std::stoi(std::string(value(word))) <= 99;
  };
  const std::string_view spindle_on = fanuc ? "M03" : "M3";
  const std::string_view spindle_ccw = fanuc ? "M04" : "M4";
  const auto spindle_word = [&](std::string_view word) {
    return word == spindle_on || word == spindle_ccw;
  };
  if (!w.empty() && starts_with(w[0], "T")) {
    if (fanuc) {  // T{tt}{tt}: tool and offset, the same number
      const bool ok = w.size() == 1 && w[0].size() == 5 && is_whole(value(w[0])) &&
                      w[0].substr(1, 2) == w[0].substr(3, 2) &&
                      tool("T" + std::string(w[0].substr(1, 2)));
      return ok ? std::nullopt : std::optional<std::string>("not the fanuc tool call T{tt}{tt}");
    }
    const bool ok = sinumerik ? w.size() == 2 && tool(w[0]) && w[1] == "D1"
                              : w.size() == 3 && tool(w[0]) && w[1] == "M6" && w[2] == "G43";
    return ok ? std::nullopt : std::optional<std::string>("not the dialect's tool call");
  }
  if (!w.empty() && (w[0] == "G96" || w[0] == "G97" || w[0] == "G50")) {
    const bool s_whole = fanuc;
    bool ok = false;
    if (w[0] == "G50") {
      ok = fanuc && w.size() == 2 && starts_with(w[1], "S") && is_positive_value(value(w[1]), true);
    } else if (w[0] == "G97") {
      ok = w.size() == 3 && starts_with(w[1], "S") && is_positive_value(value(w[1]), s_whole) &&
           spindle_word(w[2]);
    } else if (fanuc) {  // G96 S{v} M03, its limit in the G50 block before
      ok = w.size() == 3 && starts_with(w[1], "S") && is_positive_value(value(w[1]), true) &&
           spindle_word(w[2]);
    } else if (sinumerik) {  // G96 S{v} LIMS={n_max} M3
      ok = w.size() == 4 && starts_with(w[1], "S") && is_positive_value(value(w[1]), false) &&
           starts_with(w[2], "LIMS=") && is_positive_value(w[2].substr(5), false) &&
           spindle_word(w[3]);
    } else {  // G96 D{n_max} S{v} M3
      ok = w.size() == 4 && starts_with(w[1], "D") && is_positive_value(value(w[1]), false) &&
           starts_with(w[2], "S") && is_positive_value(value(w[2]), false) && spindle_word(w[3]);
    }
    return ok ? std::nullopt
              : std::optional<std::string>("not the dialect's spindle block, or a zero in it");
  }
  if (!w.empty() && (w[0] == "G4" || w[0] == "G04")) {
    const char letter = fanuc ? 'X' : sinumerik ? 'F' : 'P';
    const bool ok = w[0] == (fanuc ? "G04" : "G4") && w.size() == 2 && !w[1].empty() &&
                    w[1][0] == letter && is_positive_value(value(w[1]), false);
    return ok ? std::nullopt
              : std::optional<std::string>("not the dialect's dwell block, or a zero dwell");
  }
  constexpr std::string_view kOrder = "GXZCFSM";
  std::size_t previous_rank = 0;
  std::size_t m_words = 0;
  for (const std::string_view word : w) {
    if (sinumerik && word == "DIAMON" && previous_rank == 0) continue;
    const std::size_t rank = word.empty() ? std::string_view::npos : kOrder.find(word.front());
    if (rank == std::string_view::npos || rank < previous_rank) {
      return "a word out of G X Z C F S M or of that order: \"" + std::string(word) + "\"";
    }
    previous_rank = rank;
    m_words += word.front() == 'M' ? 1 : 0;
    const bool whole_word =
        word.front() == 'G' || word.front() == 'M' || (fanuc && word.front() == 'S');
    if (whole_word ? !is_whole(value(word)) : !is_real(value(word))) {
      return "a malformed number: " + std::string(word);
    }
    if (fanuc && (word.front() == 'G' || word.front() == 'M') && word.size() == 2) {
      return "a one-digit fanuc G or M word: " + std::string(word);
    }
    if (word.front() == 'F' && !is_positive_value(value(word), false)) {
      return "a feed that prints as zero: " + std::string(word);
    }
  }
  if (m_words > 1) return std::string("more than one M word in a block");
  return std::nullopt;
}

// The feed mode and C axis of a lathe program as its blocks go by (lathe-flat.md 6.1-6.2).
struct LatheFlatState {
  bool inverse_time = false;  // after a G93 block, until a G94 block
  bool g93_seen = false;      // a flat program: G93 is written by nothing else
  bool c_words = false;
  bool spindle_words = false;  // an S word or M3/M4 (none in a flat program)
};

// A lathe block against the flat's feed-mode rules: G93 and G94 stand alone (except G94 in the
// modal line); a C word only in a rapid (G0 C, the index with the tool clear) or in a G1 under
// G93; every G1 under G93 has its own F (its 1/T); no rapid under G93. Updates `state`.
std::optional<std::string> bad_flat_block(std::string_view line, bool fanuc,
                                          LatheFlatState& state) {
  const std::vector<std::string_view> w = block_words(line);
  const auto has = [&](std::string_view word) {
    return std::find(w.begin(), w.end(), word) != w.end();
  };
  const auto has_letter = [&](char letter) {
    return std::any_of(w.begin(), w.end(),
                       [&](std::string_view word) { return !word.empty() && word[0] == letter; });
  };
  if (has_letter('S') || has(fanuc ? "M03" : "M3") || has(fanuc ? "M04" : "M4")) {
    state.spindle_words = true;
  }
  if (has("G93")) {
    if (w.size() != 1) return std::string("G93 not alone in its block");
    state.inverse_time = state.g93_seen = true;
    return std::nullopt;
  }
  if (has("G94")) {
    if (state.inverse_time && w.size() != 1) return std::string("G94 after G93 not alone");
    state.inverse_time = false;
  }
  const bool rapid = has(fanuc ? "G00" : "G0");
  const bool feed = has(fanuc ? "G01" : "G1");
  const bool c_word = has_letter('C');
  state.c_words = state.c_words || c_word;
  if (state.inverse_time && rapid) return std::string("a rapid under G93");
  if (c_word && !rapid && !(feed && state.inverse_time)) {
    return std::string("a C word outside a rapid or a G93 G1 block");
  }
  if (feed && state.inverse_time && !has_letter('F')) {
    return std::string("a G93 block without its own F");
  }
  return std::nullopt;
}

// A lathe program: its modal block selects the XZ plane (every milling program has G17).
bool is_lathe_program(std::string_view program) {
  return program.find("\nG18 ") != std::string_view::npos ||
         program.find(" G18 ") != std::string_view::npos;
}

// The rules of spec programs.md section 3 for a pass program in any dialect: ASCII lines; comments
// `( ... )` (linuxcnc, fanuc: closed, nothing nested) or `; ...` (sinumerik); code words
// `<letter><value>` in the order G X Y Z I J C H F S T D M, one M word per block; G M H T D whole
// numbers, every other letter a real number with a decimal point (fanuc S: a whole number), never
// -0; `%` first and last (linuxcnc, fanuc) or nowhere (sinumerik); fanuc's `O{4 digits} (NAME)`
// its only O word. A lathe program (G18) has its own block rules: bad_lathe_block.
std::optional<std::string> bad_dialect_program_text(std::string_view program) {
  if (auto why = bad_ascii_lines(program)) {
    return why;
  }
  const bool sinumerik = starts_with(program, "; ");
  const bool fanuc = starts_with(program, "%\nO");
  const bool lathe = is_lathe_program(program);
  if (sinumerik ? program.find('%') != std::string_view::npos
                : !starts_with(program, "%\n") || !ends_with(program, "\nM30\n%\n")) {
    return std::string("the program's % lines are wrong for its dialect");
  }
  const auto whole = [](std::string_view text) {
    return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
      return std::isdigit(static_cast<unsigned char>(c)) != 0;
    });
  };
  LatheFlatState flat;
  std::size_t line_number = 0;
  std::size_t begin = 0;
  while (begin < program.size()) {
    const std::size_t end = program.find('\n', begin);
    std::string_view line = program.substr(begin, end - begin);
    begin = end + 1;
    const std::string where =
        "line " + std::to_string(++line_number) + " \"" + std::string(line.substr(0, 200)) + "\": ";
    if (line == "%" && !sinumerik) continue;
    if (fanuc && line_number == 2) {  // O{number} (NAME)
      if (line.size() < 8 || line[0] != 'O' || !whole(line.substr(1, 4)) ||
          line.substr(5, 2) != " (" || !ends_with(line, ")")) {
        return where + "not the fanuc O line";
      }
      continue;
    }
    if (sinumerik ? starts_with(line, ";") : starts_with(line, "(")) {
      const std::string_view text = sinumerik ? line.substr(1) : line.substr(1, line.size() - 2);
      if ((!sinumerik && !ends_with(line, ")")) ||
          text.find_first_of("();%") != std::string_view::npos) {
        return where + "a comment that breaks the dialect's comment rules";
      }
      continue;
    }
    if (lathe) {
      if (auto why = bad_lathe_block(line, fanuc, sinumerik)) return where + *why;
      if (auto why = bad_flat_block(line, fanuc, flat)) return where + *why;
      continue;
    }
    constexpr std::string_view kOrder = "GXYZIJCHFSTDM";
    std::size_t previous_rank = 0;
    std::size_t m_words = 0;
    std::size_t word_begin = 0;
    while (word_begin <= line.size()) {
      std::size_t word_end = line.find(' ', word_begin);
      if (word_end == std::string_view::npos) word_end = line.size();
      const std::string_view word = line.substr(word_begin, word_end - word_begin);
      word_begin = word_end + 1;
      const std::size_t rank = word.empty() ? std::string_view::npos : kOrder.find(word.front());
      if (rank == std::string_view::npos || rank < previous_rank) {
        return where + "a word out of G X Y Z I J C H F S T D M or of that order: \"" +
               std::string(word) + "\"";
      }
      previous_rank = rank;
      std::string_view value = word.substr(1);
      m_words += word.front() == 'M' ? 1 : 0;
      const bool integer_word =
          std::string_view("GMHTD").find(word.front()) != std::string_view::npos ||
          (fanuc && word.front() == 'S');
      if (integer_word ? !whole(value) : false)
        return where + "not a whole number: " + std::string(word);
      if (integer_word) continue;
      if (starts_with(value, "-")) value.remove_prefix(1);
      const auto dot = value.find('.');
      if (dot == std::string_view::npos || !whole(value.substr(0, dot)) ||
          !whole(value.substr(dot + 1))) {
        return where + "a real number without its decimal point: " + std::string(word);
      }
      if (word[1] == '-' && value.find_first_not_of("0.") == std::string_view::npos) {
        return where + "a -0: " + std::string(word);
      }
    }
    if (m_words > 1) return where + "more than one M word in a block";
  }
  if (flat.c_words && !flat.g93_seen) return std::string("C words in a program without G93");
  if (flat.g93_seen && flat.spindle_words) {
    return std::string("a spindle word in a flat program (the C axis is not a spindle there)");
  }
  if (flat.inverse_time) return std::string("the program ends under G93");
  return std::nullopt;
}

std::optional<std::string> broken_promise(std::string_view path, std::string_view request_body,
                                          const api::ApiResponse& response, Form form) {
  const int status = response.status;
  if (std::find(kPromisedStatuses.begin(), kPromisedStatuses.end(), status) ==
      kPromisedStatuses.end()) {
    return "status " + std::to_string(status) + " is not one of 200/400/413/415/422";
  }
  if (status == 200 && form == Form::plain_text) {
    if (response.content_type != "text/plain; charset=us-ascii") {
      return "Accept: text/plain answered with " + response.content_type;
    }
    const bool has_attachment =
        std::any_of(response.headers.begin(), response.headers.end(), [](const auto& header) {
          return header.first == "Content-Disposition" &&
                 starts_with(header.second, "attachment; filename=\"");
        });
    if (!has_attachment) {
      return "the text/plain program has no Content-Disposition: attachment";
    }
    if (auto why = bad_written_program(response.body)) {
      return why;
    }
#ifdef CUTCALC_FUZZ_OPENAPI_PATH
    return contract_violation(path, request_body, response, nlohmann::json(response.body));
#else
    return std::nullopt;
#endif
  }
  const std::string_view expected_type =
      status == 200 ? "application/json" : api::kProblemMediaType;
  if (response.content_type != expected_type) {
    return "status " + std::to_string(status) + " answered with content type " +
           response.content_type;
  }
  const nlohmann::json body = nlohmann::json::parse(response.body, nullptr, false);
  if (body.is_discarded()) {
    return std::string("the body is not JSON");
  }
  if (!body.is_object()) {
    return std::string("the body is not a JSON object");
  }
  if (!api::all_numbers_finite(body)) {
    return std::string("a NaN or infinity in the body");
  }
  if (auto negative = negative_length(body)) {
    return "a negative length or time: " + *negative;
  }
  if (status != 200) {
    if (auto why = problem_shape(body, status)) {
      return why;
    }
  } else if (writes_program(path) && body.contains("program") && body["program"].is_string()) {
    if (auto why = bad_written_program(body["program"].get<std::string>())) {
      return "the JSON answer's program: " + *why;
    }
  }
#ifdef CUTCALC_FUZZ_OPENAPI_PATH
  return contract_violation(path, request_body, response, body);
#else
  static_cast<void>(path);
  static_cast<void>(request_body);
  return std::nullopt;
#endif
}

std::size_t mutate(std::uint8_t* data, std::size_t size, std::size_t max_size, unsigned int seed) {
  Rng rng(seed);
  if (pick(rng, 2) == 0) {
    return LLVMFuzzerMutate(data, size, max_size);
  }
  nlohmann::json document = nlohmann::json::parse(data, data + size, nullptr, false);
  if (document.is_discarded()) {
    return LLVMFuzzerMutate(data, size, max_size);
  }
  const std::size_t mutations = 1 + pick(rng, 3);
  bool changed = false;
  for (std::size_t i = 0; i < mutations; ++i) {
    changed = mutate_document(document, rng) || changed;
  }
  const std::string out = pick(rng, 8) == 0 ? document.dump(1) : document.dump();
  if (!changed || out.size() > max_size) {
    return LLVMFuzzerMutate(data, size, max_size);
  }
  std::copy(out.begin(), out.end(), data);
  return out.size();
}

int run_one(std::string_view path, Form form, const std::uint8_t* data, std::size_t size) {
  const std::string_view body(reinterpret_cast<const char*>(data), size);
  const api::ApiRequest request{path, "application/json", body, "fuzz",
                                form == Form::plain_text ? std::string_view("text/plain")
                                                         : std::string_view("application/json")};
  api::ApiResponse response = api::run_json_endpoint(request, handler_for(path));
  api::write_whole(response);
  if (auto why = broken_promise(path, body, response, form)) {
    report_and_abort(*why, response, body);
  }
  return 0;
}

}  // namespace cutcalc::fuzz
