#pragma once
// The calculation route table (api/routes.h) as JSON, for the consumers that are not C++: the
// fuzz scripts, the reference replay, the code generator check and the browser tests read it from
// `cutcalc --routes`. One object per route, in table order:
//   {"path", "slug", "forms": ["json"] or ["json", "plain_text"],
//    "plot_field": {"name", "example", "replaces"} or null,
//    "reference_files": ["entry-length.json", "next/..."], "next_reference_files": ["next/..."],
//    "page_section": "entry" or null, "page_module": "sections/entry.js" or null,
//    "heavy": true or false, "max_body_bytes": 0 (the service's default) or its own limit}

#include <nlohmann/json.hpp>

namespace cutcalc::api {

nlohmann::json calculation_routes_json();

}  // namespace cutcalc::api
