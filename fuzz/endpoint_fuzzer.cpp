// The one libFuzzer harness of the calculation endpoints: arbitrary bytes as the JSON body of a
// POST to the route CUTCALC_FUZZ_ROUTE (a path of api/routes.cpp) asking for the answer form
// CUTCALC_FUZZ_FORM (json or plain_text), through the service's own pipeline
// (api::run_json_endpoint with the route's handler), with the API's promises checked on every
// answer (fuzz/fuzz_support.h). scripts/ci-fuzz.sh runs it once per (route, form) of the table,
// each run with its own corpus and time, as the harnesses <slug>_fuzzer and <slug>_text_fuzzer
// (the rows cutcalc_fuzz_seeds writes to harnesses.txt).

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "api/routes.h"
#include "fuzz/fuzz_support.h"

namespace {

std::string g_path;
cutcalc::fuzz::Form g_form = cutcalc::fuzz::Form::json;

[[noreturn]] void refuse(const std::string& why) {
  std::fprintf(stderr, "endpoint_fuzzer: %s\n  routes:", why.c_str());
  for (const cutcalc::api::CalculationRoute& route : cutcalc::api::calculation_routes()) {
    std::fprintf(stderr, " %s", route.path);
  }
  std::fprintf(stderr, "\n");
  std::exit(2);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  const char* path = std::getenv("CUTCALC_FUZZ_ROUTE");
  const char* form = std::getenv("CUTCALC_FUZZ_FORM");
  if (path == nullptr) {
    refuse("set CUTCALC_FUZZ_ROUTE to a calculation route");
  }
  const cutcalc::api::CalculationRoute* route = cutcalc::api::find_calculation_route(path);
  if (route == nullptr) {
    refuse(std::string("no calculation route ") + path);
  }
  const std::string_view form_name = form == nullptr ? "json" : form;
  if (form_name == "plain_text" &&
      route->forms == cutcalc::api::AnswerForms::json_and_plain_text_program) {
    g_form = cutcalc::fuzz::Form::plain_text;
  } else if (form_name != "json") {
    refuse(std::string(path) + " has no answer form " + std::string(form_name));
  }
  g_path = path;
  return 0;
}

extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size,
                                               std::size_t max_size, unsigned int seed) {
  return cutcalc::fuzz::mutate(data, size, max_size, seed);
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return cutcalc::fuzz::run_one(g_path, g_form, data, size);
}
