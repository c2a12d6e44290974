#pragma once
// Domain results of paper 002 -> response JSON (field names of API.md).

#include <nlohmann/json.hpp>

#include "api/json_writer.h"

#include "domain/entry/entry_length.h"
#include "domain/entry/entry_scheme.h"
#include "domain/entry/main_time.h"

namespace cutcalc::api::entry {

nlohmann::json to_json(const domain::entry::Position& position);
// The entry-length answer; `scheme`, when given, is its plan-view scheme (to_json(EntryScheme)).
JsonText entry_length_answer(const domain::entry::EntryLengthResult& result,
                             const nlohmann::json* scheme);
// The opt-in `scheme` of POST /v1/entry-length (include_scheme).
nlohmann::json to_json(const domain::entry::EntryScheme& scheme);
nlohmann::json to_json(const domain::entry::MainTimeResult& result);

}  // namespace cutcalc::api::entry
