#pragma once
// A JSON object whose first member is a long string written as it is read (a program of many
// megabytes): `{"<key>":"<the source, escaped>",<the other members>}`. The other members are
// known before the first byte leaves, except what `after` adds once the string is written (a
// member that costs time and that the string does not need). A number `after` makes NaN or
// infinite cuts the body short (a bug: it cannot become a 500 once the status is sent).

#include <functional>
#include <memory>
#include <string_view>

#include <nlohmann/json.hpp>

#include "domain/common/text_source.h"

namespace cutcalc::api {

std::unique_ptr<domain::TextSource> json_with_streamed_string(
    std::string_view key, std::unique_ptr<domain::TextSource> value, nlohmann::json rest,
    std::function<void(nlohmann::json&)> after = {});

}  // namespace cutcalc::api
