#pragma once
// Logging set-up (spdlog) and the access log: one line per request, as text or JSON.

#include <string>
#include <string_view>

#include "service/config.h"

namespace cutcalc::service {

// Installs the default logger on stdout in UTC with the chosen level and format.
void setup_logging(const std::string& level, LogFormat format);

struct AccessRecord {
  std::string_view method;
  std::string_view path;
  int status = 0;
  double duration_ms = 0.0;
  std::string_view request_id;
  std::string_view remote_addr;
};

// False when the access log would drop the record (checked before building one).
bool access_log_enabled();
void log_access(const AccessRecord& record);

// A JSON string literal for `text` (quotes included), invalid UTF-8 replaced.
std::string json_quoted(std::string_view text);

}  // namespace cutcalc::service
