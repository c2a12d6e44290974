// cutcalc: composes configuration, logging, signals and the HTTP app; nothing else lives here.

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>

#include "api/route_table_json.h"
#include "service/build_info.h"
#include "service/config.h"
#include "service/cpu_budget.h"
#include "service/http_app.h"
#include "service/http_tuning.h"
#include "service/logging.h"
#include "service/signals.h"

int main(int argc, char** argv) {
  using namespace cutcalc::service;
  const std::vector<std::string> args(argv + 1, argv + argc);
  const ConfigOutcome outcome =
      parse_config(args, [](const char* name) { return std::getenv(name); });
  if (outcome.print_routes) {
    std::puts(cutcalc::api::calculation_routes_json().dump(2).c_str());
    return 0;
  }
  if (!outcome.config) {
    const std::string text = outcome.print_version ? "cutcalc " + std::string(build_version()) +
                                                         " (" + std::string(build_commit()) + ")\n"
                                                   : outcome.message + "\n";
    std::fputs(text.c_str(), outcome.exit_code == 0 ? stdout : stderr);
    return outcome.exit_code;
  }
  const Config& config = *outcome.config;
  setup_logging(config.log_level, config.log_format);

  ShutdownSignals signals;  // before any thread starts, so that all of them inherit the mask
  HttpApp app(config);
  const int port = app.bind();
  if (port < 0) {
    spdlog::critical("cannot listen on {}:{}: {}", config.host, config.port, app.bind_error());
    return 1;
  }
  signals.on_shutdown([&app](const char* signal_name) {
    spdlog::info("{} received: finishing in-flight requests, then exiting", signal_name);
    app.shutdown();
  });
  spdlog::info("cutcalc {} listening on http://{}:{}", build_version(), config.host, port);
  spdlog::info("event loops: {}; the CPUs this process may use: {}",
               effective_event_loop_threads(config.http), describe(read_cpu_budget()));
  const EventLoopSettings settings = event_loop_settings(config.http);
  spdlog::info(
      "connections at most: {}; memory budget for large bodies and waiting answers: {} MiB",
      settings.max_connections, settings.memory_budget_bytes / (1024 * 1024));
  const bool served = app.serve();
  spdlog::info("stopped");
  return served ? 0 : 1;
}
