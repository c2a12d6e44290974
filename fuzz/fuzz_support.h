#pragma once
// Shared body of the libFuzzer harness of the endpoints (fuzz/endpoint_fuzzer.cpp): arbitrary bytes
// go through api::run_json_endpoint with the handler api::calculation_routes() registers for the
// path, exactly as the service calls it, and every promise of the API is checked on the answer.
// A broken promise prints what was broken and calls abort(), so libFuzzer keeps the input.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "api/api_response.h"

namespace cutcalc::fuzz {

// Which form of the answer the request asks for (the Accept header).
enum class Form {
  json,        // Accept: application/json
  plain_text,  // Accept: text/plain (a route whose row has the text form: a program)
};

// Runs one fuzz input as the body of a POST to `path` and checks the answer; returns 0.
int run_one(std::string_view path, Form form, const std::uint8_t* data, std::size_t size);

// libFuzzer's custom mutator (LLVMFuzzerCustomMutator): half of the time, and always when the
// input is not JSON, libFuzzer's own byte mutations (with the -dict tokens), which explore the
// parser; otherwise the input is parsed and one to three structural mutations are applied, then
// it is written out again: a number replaced by an edge value (0, -0, the field bounds 1e-6 and
// 1e6 and their neighbours, huge, subnormal) or tweaked (sign, x10, /10, +-1, next double,
// scaled), a whole number made fractional, a string swapped for a choice of the API, a member or
// element removed or copied elsewhere, a value replaced by another JSON type. So most mutants are
// valid JSON and reach validation and the domain instead of stopping in the parser.
std::size_t mutate(std::uint8_t* data, std::size_t size, std::size_t max_size, unsigned int seed);

// The checks run_one makes on the answer to `request_body` sent to `path`: the status is one of
// 200/400/413/415/422; a JSON body parses, is an object, has no NaN or infinity and no negative
// length (is_non_negative_key); a problem has the RFC 9457 members (a 422 at least one error); a
// text/plain program passes bad_program_text. With CUTCALC_FUZZ_OPENAPI_PATH defined (the CMake
// project does) also: the response conforms to its schema in openapi.yaml, and a request the
// service answered with 200 conforms to the request schema. What is wrong, or nullopt.
std::optional<std::string> broken_promise(std::string_view path, std::string_view request_body,
                                          const api::ApiResponse& response, Form form);

// A key whose number (or list of numbers) must never be negative: a length, size or time. Keys
// ending in _mm, _mm2, _um or _min (minutes, not rates such as _m_per_min, which are signed
// speeds), except the signed coordinates and offsets x_mm, y_mm, offset_mm and axis_y_mm (and the
// others of support/quantity_keys.h).
bool is_non_negative_key(std::string_view key);

// The first negative number under a non-negative key, as "pointer = value", or nullopt.
std::optional<std::string> negative_length(const nlohmann::json& body);

// What is wrong with a G-code program sent as text/plain; nullopt when it is plain ASCII, every
// comment is closed on its line and no word outside comments is written as nan or inf.
std::optional<std::string> bad_program_text(std::string_view program);

// What is wrong with a program in a dialect (a mill or a lathe program: every route whose row
// has the text/plain form writes one, the polygon with a `program` object), against the text
// rules of spec programs.md section 3, grooving-cycle.md section 5.2 and lathe-flat.md section
// 6.2; nullopt when nothing is.
std::optional<std::string> bad_dialect_program_text(std::string_view program);

}  // namespace cutcalc::fuzz
