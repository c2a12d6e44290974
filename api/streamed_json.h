#pragma once
// A JSON object whose first member is a long string written as it is read (a program of many
// megabytes): `{"<key>":"<the source, escaped>",<the other members>}`. The other members are
// known before the first byte leaves; only the string streams.

#include <memory>
#include <string_view>

#include <nlohmann/json.hpp>

#include "domain/common/text_source.h"

namespace cutcalc::api {

std::unique_ptr<domain::TextSource> json_with_streamed_string(
    std::string_view key, std::unique_ptr<domain::TextSource> value, const nlohmann::json& rest);

}  // namespace cutcalc::api
