#include "service/config.h"

#include <array>
#include <charconv>
#include <string>
#include <string_view>

namespace cutcalc::service {
namespace {

struct Setting {
  const char* flag;  // --port
  const char* env;   // CUTCALC_PORT
};

constexpr std::array kSettings = {
    Setting{"--host", "CUTCALC_HOST"},
    Setting{"--port", "CUTCALC_PORT"},
    Setting{"--threads", "CUTCALC_THREADS"},
    Setting{"--log-level", "CUTCALC_LOG_LEVEL"},
    Setting{"--log-format", "CUTCALC_LOG_FORMAT"},
    Setting{"--cors-origin", "CUTCALC_CORS_ORIGINS"},
    Setting{"--calculation-threads", "CUTCALC_CALCULATION_THREADS"},
    Setting{"--calculation-queue", "CUTCALC_CALCULATION_QUEUE"},
    Setting{"--calculation-timeout-ms", "CUTCALC_CALCULATION_TIMEOUT_MS"},
    Setting{"--reuse-port", "CUTCALC_REUSE_PORT"},
    Setting{"--keep-alive-timeout-s", "CUTCALC_KEEP_ALIVE_TIMEOUT_S"},
    Setting{"--lame-duck-ms", "CUTCALC_LAME_DUCK_MS"},
    Setting{"--max-connections", "CUTCALC_MAX_CONNECTIONS"},
    Setting{"--memory-limit-mb", "CUTCALC_MEMORY_LIMIT_MB"},
};

// A flag that may stand alone, meaning "on".
constexpr std::string_view kSwitch = "--reuse-port";

std::optional<long> parse_long(std::string_view text, long min, long max) {
  long value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < min || value > max) {
    return std::nullopt;
  }
  return value;
}

// Applies one setting; returns an error message, empty on success.
std::string apply(Config& config, std::string_view flag, const std::string& value) {
  if (flag == "--host") {
    if (value.empty()) {
      return "--host must not be empty";
    }
    config.host = value;
  } else if (flag == "--port") {
    const auto port = parse_long(value, 0, 65535);
    if (!port) {
      return "--port must be an integer 0..65535 (0 picks a free port), got '" + value + "'";
    }
    config.port = static_cast<int>(*port);
  } else if (flag == "--threads") {
    const auto threads = parse_long(value, 1, 256);
    if (!threads) {
      return "--threads must be an integer 1..256, got '" + value + "'";
    }
    config.http.event_loop_threads = static_cast<std::size_t>(*threads);
  } else if (flag == "--log-level") {
    constexpr std::array levels = {"trace", "debug", "info", "warn", "error", "critical", "off"};
    for (const char* level : levels) {
      if (value == level) {
        config.log_level = value;
        return {};
      }
    }
    return "--log-level must be one of trace, debug, info, warn, error, critical, off; got '" +
           value + "'";
  } else if (flag == "--cors-origin") {
    // Repeatable, or comma-separated: exact origins such as https://mes.example, or "*".
    std::string_view rest = value;
    while (!rest.empty()) {
      const auto comma = rest.find(',');
      const std::string_view origin = rest.substr(0, comma);
      if (!origin.empty()) {
        config.cors_origins.emplace_back(origin);
      }
      rest = comma == std::string_view::npos ? std::string_view{} : rest.substr(comma + 1);
    }
  } else if (flag == "--calculation-threads") {
    const auto threads = parse_long(value, 1, 256);
    if (!threads) {
      return "--calculation-threads must be an integer 1..256, got '" + value + "'";
    }
    config.http.calculation_threads = static_cast<std::size_t>(*threads);
  } else if (flag == "--calculation-queue") {
    const auto queue = parse_long(value, 1, 100000);
    if (!queue) {
      return "--calculation-queue must be an integer 1..100000, got '" + value + "'";
    }
    config.http.calculation_queue_limit = static_cast<std::size_t>(*queue);
  } else if (flag == "--calculation-timeout-ms") {
    const auto ms = parse_long(value, 1, 3600000);
    if (!ms) {
      return "--calculation-timeout-ms must be an integer 1..3600000, got '" + value + "'";
    }
    config.http.limits.calculation_timeout = std::chrono::milliseconds(*ms);
  } else if (flag == "--keep-alive-timeout-s") {
    const auto seconds = parse_long(value, 1, 3600);
    if (!seconds) {
      return "--keep-alive-timeout-s must be an integer 1..3600, got '" + value + "'";
    }
    config.http.limits.keep_alive_timeout = std::chrono::seconds(*seconds);
  } else if (flag == "--lame-duck-ms") {
    const auto ms = parse_long(value, 0, 600000);
    if (!ms) {
      return "--lame-duck-ms must be an integer 0..600000, got '" + value + "'";
    }
    config.http.limits.lame_duck = std::chrono::milliseconds(*ms);
  } else if (flag == "--max-connections") {
    const auto connections = parse_long(value, 1, 1000000);
    if (!connections) {
      return "--max-connections must be an integer 1..1000000, got '" + value + "'";
    }
    config.http.max_connections = static_cast<std::size_t>(*connections);
  } else if (flag == "--memory-limit-mb") {
    const auto mib = parse_long(value, 64, 1048576);
    if (!mib) {
      return "--memory-limit-mb must be an integer 64..1048576, got '" + value + "'";
    }
    config.http.memory_limit_bytes = static_cast<std::uint64_t>(*mib) * 1024 * 1024;
  } else if (flag == kSwitch) {
    if (value == "on" || value == "true" || value == "1") {
      config.http.reuse_port = true;
    } else if (value == "off" || value == "false" || value == "0") {
      config.http.reuse_port = false;
    } else {
      return "--reuse-port takes on or off, got '" + value + "'";
    }
  } else if (flag == "--log-format") {
    if (value == "text") {
      config.log_format = LogFormat::text;
    } else if (value == "json") {
      config.log_format = LogFormat::json;
    } else {
      return "--log-format must be text or json, got '" + value + "'";
    }
  }
  return {};
}

}  // namespace

std::string usage() {
  return std::string(
      "usage: cutcalc [--host H] [--port P] [--threads N] [--log-level L] [--log-format F]\n"
      "               [--cors-origin ORIGIN ...] [--calculation-threads N]\n"
      "               [--calculation-queue N] [--calculation-timeout-ms MS]\n"
      "               [--reuse-port] [--keep-alive-timeout-s S]\n"
      "               [--lame-duck-ms MS] [--max-connections N] [--memory-limit-mb M]\n"
      "  --host H        address to listen on (default 127.0.0.1; env CUTCALC_HOST)\n"
      "  --port P        TCP port, 0 = any free port (default 8080; env CUTCALC_PORT)\n"
      "  --threads N     event-loop threads serving connections and requests\n"
      "                  (default: one per usable CPU: the affinity mask, capped by\n"
      "                  the cgroup's cpu.max quota; env CUTCALC_THREADS)\n"
      "  --log-level L   trace|debug|info|warn|error|critical|off (default info;\n"
      "                  env CUTCALC_LOG_LEVEL)\n"
      "  --log-format F  text|json (default text; env CUTCALC_LOG_FORMAT)\n"
      "  --cors-origin O origin allowed to call from a browser, e.g. https://mes.example;\n"
      "                  repeatable or comma-separated, * for any (default none;\n"
      "                  env CUTCALC_CORS_ORIGINS)\n"
      "  --calculation-threads N  threads for the calculations that can be heavy (the\n"
      "                  programs), off the event loops (default: as many as the\n"
      "                  event loops; env CUTCALC_CALCULATION_THREADS)\n"
      "  --calculation-queue N  such calculations waiting for a thread at most; beyond,\n"
      "                  503 with Retry-After (default " +
      std::to_string(HttpTuning{}.calculation_queue_limit) +
      "; env CUTCALC_CALCULATION_QUEUE)\n"
      "  --calculation-timeout-ms MS  such a calculation is stopped and answered 503\n"
      "                  with Retry-After when it has not ended MS ms after it was\n"
      "                  handed over, queue wait included (default " +
      std::to_string(HttpLimits{}.calculation_timeout.count()) +
      "; env CUTCALC_CALCULATION_TIMEOUT_MS)\n"
      "  --reuse-port    share the port with other processes (SO_REUSEPORT); without\n"
      "                  it a port in use is an error (env CUTCALC_REUSE_PORT=on|off)\n"
      "  --keep-alive-timeout-s S  an idle keep-alive connection closes after S s\n"
      "                  (default " +
      std::to_string(HttpLimits{}.keep_alive_timeout.count()) +
      ", above proxies' 60 s; env CUTCALC_KEEP_ALIVE_TIMEOUT_S)\n"
      "  --lame-duck-ms MS  at SIGTERM, /readyz answers 503 and the port stays open this\n"
      "                  long, every answer saying Connection: close, before the\n"
      "                  listener closes (default " +
      std::to_string(HttpLimits{}.lame_duck.count()) +
      "; env CUTCALC_LAME_DUCK_MS)\n"
      "  --max-connections N  open connections at most, beyond: 503 (default: what the\n"
      "                  cgroup memory limit holds, and the descriptor limit;\n"
      "                  env CUTCALC_MAX_CONNECTIONS)\n"
      "  --memory-limit-mb M  the memory the process may use, for the connection cap and\n"
      "                  the memory budget of large bodies and answers waiting for\n"
      "                  their clients; beyond it such work gets 503 (default: the\n"
      "                  cgroup's memory.max, else 256 for the budget;\n"
      "                  env CUTCALC_MEMORY_LIMIT_MB)\n"
      "  --routes        print the calculation endpoints as JSON and exit (for the tools)\n"
      "  --help, --version\n");
}

ConfigOutcome parse_config(const std::vector<std::string>& args,
                           const std::function<const char*(const char*)>& getenv) {
  Config config;
  for (const Setting& setting : kSettings) {
    if (const char* value = getenv(setting.env); value != nullptr) {
      if (auto error = apply(config, setting.flag, value); !error.empty()) {
        return {std::nullopt, std::string(setting.env) + ": " + error, 2};
      }
    }
  }
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string_view arg = args[i];
    if (arg == "--help" || arg == "-h") {
      return {std::nullopt, usage(), 0, false};
    }
    if (arg == "--version") {
      return {std::nullopt, {}, 0, true};
    }
    if (arg == "--routes") {
      return {std::nullopt, {}, 0, false, true};
    }
    std::string value;
    std::string_view flag = arg;
    if (const auto equals = arg.find('='); equals != std::string_view::npos) {
      flag = arg.substr(0, equals);
      value = std::string(arg.substr(equals + 1));
    } else if (arg == kSwitch) {
      value = "on";
    } else if (i + 1 < args.size()) {
      value = args[++i];
    } else {
      return {std::nullopt, std::string(arg) + " needs a value\n" + usage(), 2};
    }
    bool known = false;
    for (const Setting& setting : kSettings) {
      known = known || flag == setting.flag;
    }
    if (!known) {
      return {std::nullopt, "unknown option " + std::string(flag) + "\n" + usage(), 2};
    }
    if (auto error = apply(config, flag, value); !error.empty()) {
      return {std::nullopt, error, 2};
    }
  }
  return {config, {}, 0};
}

}  // namespace cutcalc::service
