// libFuzzer harness: arbitrary bytes as the JSON body of POST /v1/resultant-speeds, through the
// service's own pipeline (api::run_json_endpoint with the handler api/routes.cpp registers), with
// the API's promises checked on every answer (fuzz/fuzz_support.h). Build and run:
// scripts/ci-fuzz.sh.

#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_support.h"

extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size,
                                               std::size_t max_size, unsigned int seed) {
  return cutcalc::fuzz::mutate(data, size, max_size, seed);
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return cutcalc::fuzz::run_one("/v1/resultant-speeds", cutcalc::fuzz::Form::json, data, size);
}
