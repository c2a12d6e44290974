#pragma once
// Service settings from command-line flags and CUTCALC_* environment variables (flags win).

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "service/http_tuning.h"

namespace cutcalc::service {

enum class LogFormat { text, json };

struct Config {
  std::string host = "127.0.0.1";
  int port = 8080;
  std::string log_level = "info";  // trace, debug, info, warn, error, critical, off
  LogFormat log_format = LogFormat::text;
  std::vector<std::string> cors_origins;  // browser origins allowed to call; none by default
  HttpTuning http;
};

struct ConfigOutcome {
  std::optional<Config> config;  // absent: exit with `exit_code` after printing `message`
  std::string message;
  int exit_code = 0;
  bool print_version = false;
  bool print_routes =
      false;  // --routes: the calculation route table as JSON (api/route_table_json.h)
};

// args excludes argv[0]; getenv reads the environment (injectable for tests).
ConfigOutcome parse_config(const std::vector<std::string>& args,
                           const std::function<const char*(const char*)>& getenv);

std::string usage();

}  // namespace cutcalc::service
