#pragma once
// The one catalogue of what the API says about a program's warnings (warnings[].message): every
// code of domain/program/warning_codes.def with its sentence in each language the API speaks, as
// the error catalogue (api/error_catalogue.h) does for errors. The warning's detail stays the
// domain's English with the numbers, as the program's comment line says it (controls may not show
// Cyrillic); the message is the sentence in the answer's language, chosen by Accept-Language.

#include <optional>
#include <span>
#include <string_view>

#include <nlohmann/json.hpp>

#include "api/error_catalogue.h"
#include "domain/program/program_warning.h"

namespace cutcalc::api {

// Every warning code, in the order of the one list.
std::span<const domain::program::WarningCode> all_warning_codes();
// The code whose wire name is `name`, if there is one.
std::optional<domain::program::WarningCode> warning_code_named(std::string_view name);

// The sentence for `code` in `language` (no numbers: those are in the detail).
std::string_view warning_message(domain::program::WarningCode code, Language language);

// Gives every item of every warnings[] list of `answer` (its own member and those of its member
// objects, such as machine_time.warnings) its message in `language`. Handlers write a warning's
// code and detail only (program::to_json), since only the pipeline knows the request's language,
// as with problem details. Returns whether the answer has a warnings[] list: then its text depends
// on the language.
bool add_warning_messages(nlohmann::json& answer, Language language);

}  // namespace cutcalc::api
