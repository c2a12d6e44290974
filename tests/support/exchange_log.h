#pragma once
// Every HTTP exchange a test makes through a logged client is appended to one JSON-lines log;
// after the tests, the ctest step ContractCheck.EveryLoggedAnswerMatchesOpenApi checks every answer
// in it against openapi.yaml (tools/contract/check.mjs exchanges). The log is the file named by
// the environment variable CUTCALC_EXCHANGE_LOG, else CUTCALC_EXCHANGE_LOG at build time.

#include <httplib.h>

namespace cutcalc::testing {

// Makes `client` append every exchange it completes to the log.
void log_exchanges(httplib::Client& client);

}  // namespace cutcalc::testing
