#include "service/logging.h"

#include <memory>

#include <spdlog/pattern_formatter.h>
#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>
#include <nlohmann/json.hpp>

namespace cutcalc::service {
namespace {

LogFormat g_format = LogFormat::text;
std::shared_ptr<spdlog::logger> g_access;  // separate so that JSON access lines are flat objects

// %j: the message as a JSON string literal, so that every JSON log line is valid JSON.
class JsonMessageFlag final : public spdlog::custom_flag_formatter {
 public:
  void format(const spdlog::details::log_msg& msg, const std::tm& /*time*/,
              spdlog::memory_buf_t& dest) override {
    const std::string quoted =
        json_quoted(std::string_view(msg.payload.data(), msg.payload.size()));
    dest.append(quoted.data(), quoted.data() + quoted.size());
  }
  [[nodiscard]] std::unique_ptr<custom_flag_formatter> clone() const override {
    return std::make_unique<JsonMessageFlag>();
  }
};

}  // namespace

std::string json_quoted(std::string_view text) {
  return nlohmann::json(std::string(text))
      .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

void setup_logging(const std::string& level, LogFormat format) {
  g_format = format;
  // One sink each: a sink holds one formatter, and the two line layouts differ in JSON mode.
  auto app = std::make_shared<spdlog::logger>("cutcalc",
                                              std::make_shared<spdlog::sinks::stdout_sink_mt>());
  g_access =
      std::make_shared<spdlog::logger>("access", std::make_shared<spdlog::sinks::stdout_sink_mt>());
  auto app_format = std::make_unique<spdlog::pattern_formatter>(spdlog::pattern_time_type::utc);
  auto access_format = std::make_unique<spdlog::pattern_formatter>(spdlog::pattern_time_type::utc);
  if (format == LogFormat::json) {
    app_format->add_flag<JsonMessageFlag>('j').set_pattern(
        R"({"time":"%Y-%m-%dT%H:%M:%S.%fZ","level":"%l","message":%j})");
    // Access messages are JSON members already: the line stays one flat object.
    access_format->set_pattern(R"({"time":"%Y-%m-%dT%H:%M:%S.%fZ","level":"%l",%v})");
  } else {
    app_format->set_pattern("%Y-%m-%dT%H:%M:%S.%fZ %l %v");
    access_format->set_pattern("%Y-%m-%dT%H:%M:%S.%fZ %l %v");
  }
  app->set_formatter(std::move(app_format));
  g_access->set_formatter(std::move(access_format));
  for (const auto& logger : {app, g_access}) {
    logger->set_level(spdlog::level::from_str(level));
    logger->flush_on(spdlog::level::info);
  }
  spdlog::set_default_logger(std::move(app));
}

bool access_log_enabled() { return g_access && g_access->should_log(spdlog::level::info); }

void log_access(const AccessRecord& record) {
  if (!g_access || !g_access->should_log(spdlog::level::info)) {
    return;
  }
  if (g_format == LogFormat::json) {
    g_access->info(
        R"("event":"access","method":{},"path":{},"status":{},"duration_ms":{:.3f},"request_id":{},"remote_addr":{})",
        json_quoted(record.method), json_quoted(record.path), record.status, record.duration_ms,
        json_quoted(record.request_id), json_quoted(record.remote_addr));
  } else {
    g_access->info("access {} {} {} {:.3f}ms request_id={} remote={}", record.method,
                   json_quoted(record.path), record.status, record.duration_ms, record.request_id,
                   record.remote_addr);
  }
}

}  // namespace cutcalc::service
