#include "service/http_app.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <exception>
#include <string>
#include <utility>

#include <spdlog/spdlog.h>
#include <nlohmann/json.hpp>

#include "api/accept_header.h"
#include "api/json_endpoint.h"
#include "api/problem.h"
#include "api/routes.h"
#include "domain/common/ascii_text.h"
#include "domain/common/interruption.h"
#include "service/build_info.h"
#include "service/http_tuning.h"
#include "service/logging.h"
#include "service/request_id.h"
#include "service/web_assets.h"

namespace cutcalc::service {
namespace {

using Clock = std::chrono::steady_clock;

constexpr const char* kRequestIdHeader = "X-Request-Id";
constexpr const char* kNoSniffHeader = "X-Content-Type-Options";
// What a client refused by a full calculation pool is told to wait: the queue drains in well
// under a second at the largest programs' tens of milliseconds each.
constexpr int kBusyRetryAfterSeconds = 1;
// The status the metrics and the access log give a calculation whose client went before its answer.
constexpr int kClientClosedRequest = 499;

void write(HttpResponse& res, api::ApiResponse&& response) {
  res.status = response.status;
  for (auto& [name, value] : response.headers) {
    // One Vary field: the CORS policy may have set one already (Origin).
    if (name == "Vary") {
      if (auto said = std::find_if(res.headers.begin(), res.headers.end(),
                                   [](const ResponseHeader& h) { return h.name == "Vary"; });
          said != res.headers.end()) {
        said->value += ", " + value;
        continue;
      }
    }
    res.headers.push_back({std::move(name), std::move(value)});
  }
  res.body = std::move(response.body);
  res.content_type = std::move(response.content_type);
  res.body_source = std::move(response.body_source);
}

// The request headers cutcalc reads, each the first of its name, found in one pass.
struct ReadHeaders {
  std::string_view content_type;
  std::string_view accept;
  std::string_view accept_language;
  std::string_view request_id;
  std::string_view origin;
};

ReadHeaders read_headers(const HttpRequest& req) {
  ReadHeaders read;
  bool content_type = false;
  bool accept = false;
  bool accept_language = false;
  bool request_id = false;
  bool origin = false;
  const auto take = [](bool& taken, std::string_view& into, std::string_view value) {
    if (!taken) {
      taken = true;
      into = value;
    }
  };
  for (const HeaderField& field : req.fields) {
    if (domain::iequals_ascii(field.name, "Content-Type")) {
      take(content_type, read.content_type, field.value);
    } else if (domain::iequals_ascii(field.name, "Accept")) {
      take(accept, read.accept, field.value);
    } else if (domain::iequals_ascii(field.name, "Accept-Language")) {
      take(accept_language, read.accept_language, field.value);
    } else if (domain::iequals_ascii(field.name, kRequestIdHeader)) {
      take(request_id, read.request_id, field.value);
    } else if (domain::iequals_ascii(field.name, "Origin")) {
      take(origin, read.origin, field.value);
    }
  }
  return read;
}

// The problem's `instance` of a request: the path of its target
// (percent-encoded where it is not a plain URI character), or "/" when none could be read.
std::string problem_instance(std::string_view target) {
  target = target.substr(0, target.find_first_of("?#"));
  if (target.empty() || target.front() != '/') return "/";
  std::string instance;
  for (const char c : target) {
    const bool plain = std::isalnum(static_cast<unsigned char>(c)) != 0 ||
                       std::string_view("-._~!$&'()*+,;=:@/%").find(c) != std::string_view::npos;
    if (plain) {
      instance += c;
    } else {
      constexpr char kHex[] = "0123456789ABCDEF";
      const auto byte = static_cast<unsigned char>(c);
      instance += '%';
      instance += kHex[byte >> 4U];
      instance += kHex[byte & 0xFU];
    }
  }
  return instance;
}

api::Problem problem(api::ProblemKind kind, api::ErrorCode code,
                     nlohmann::json params = nlohmann::json::object()) {
  return {kind, api::Message{code, std::move(params)}, {}};
}

// The catalogue's code for what the engine refused: the one of the same name.
api::ErrorCode engine_error_code(HttpFault fault) {
  switch (fault) {
#define CUTCALC_HTTP_FAULT(name, status) \
  case HttpFault::name:                  \
    return api::ErrorCode::name;
#include "service/http_faults.def"
#undef CUTCALC_HTTP_FAULT
  }
  return api::ErrorCode::internal_error;  // unreachable: the switch names every fault
}

api::ProblemKind engine_problem_kind(HttpFault fault) {
  switch (http_status(fault)) {
    case 413:
      return api::ProblemKind::payload_too_large;
    case 503:
      return api::ProblemKind::unavailable;
    default:
      return api::ProblemKind::bad_request;
  }
}

void reply_json(HttpResponse& res, const nlohmann::json& body) {
  res.status = 200;
  res.set_content(body.dump(), "application/json");
}

}  // namespace

// One request's bookkeeping: what its metrics, access log and problem bodies need, owned, so that
// a calculation on the pool can finish the request after the request's views are gone.
struct HttpApp::Exchange {
  Clock::time_point start;
  const char* route = "unmatched";  // metric label: a known path or "unmatched", never user text
  std::string method;  // a metric label (Metrics::observe maps it to a static one); owned: a
                       // calculation settles after the request's buffers are gone
  std::string path;    // the request's path, for the log and problem instances
  std::string request_id;
  std::string remote;  // the peer's address, when the access log is on
  api::Language language = api::Language::en;

  void write_problem(HttpResponse& res, const api::Problem& said) const {
    write(res, api::problem_response(said, problem_instance(path), request_id, language));
  }
};

HttpApp::HttpApp(Config config) : config_(std::move(config)), cors_(config_.cors_origins) {
  install_routes();
  for (const api::CalculationRoute& route : api::calculation_routes()) {
    if (route.max_body_bytes > config_.http.limits.max_body_bytes) {
      config_.http.limits.large_body_routes.emplace_back(route.path, route.max_body_bytes);
    }
  }
  engine_ = std::make_unique<EventLoopEngine>(
      event_loop_settings(config_.http),
      [this](const HttpRequest& request) { return answer(request); },
      [this](const EngineError& error) { return engine_error_response(error); },
      [this] {
        return listener_.stopped() ? ServerPhase::stopped
               : draining_.load()  ? ServerPhase::draining
                                   : ServerPhase::serving;
      },
      counters_);
}

HttpApp::~HttpApp() = default;

int HttpApp::bind() {
  return listener_.open(
      {config_.host, config_.port, config_.http.listen_backlog, config_.http.reuse_port});
}

bool HttpApp::serve() {
  const bool served = listener_.run([this](int sock) { engine_->adopt(sock); });
  // The listener is closed; answer what is in flight before the caller tears the app down.
  const auto limit = std::max(config_.http.limits.request_timeout, std::chrono::milliseconds{1000});
  if (!engine_->drain(limit)) {
    spdlog::warn("shutdown: requests still in flight after {} ms were dropped", limit.count());
  }
  return served;
}

void HttpApp::shutdown() {
  draining_.store(true);
  listener_.stop(config_.http.limits.lame_duck);
}

void HttpApp::serve_connection(int sock) { engine_->adopt(sock); }

std::string HttpApp::engine_error_response(const EngineError& error) {
  // What the head said of its language, as far as it was read; English where it was not.
  const bool negotiated = !error.accept_language.empty();
  const api::Language language = api::preferred_language(error.accept_language);
  nlohmann::json params = nlohmann::json::object();
  if (error.retry_after_s > 0) params["retry_after_s"] = error.retry_after_s;
  const api::Problem said{engine_problem_kind(error.fault),
                          api::Message{engine_error_code(error.fault), std::move(params)},
                          {}};
  const std::string request_id = generate_request_id();
  const std::string instance = problem_instance(error.target);
  HttpResponse res;
  res.headers = cors_.rejection_headers(error.origin);
  write(res, api::problem_response(
                 said, instance, request_id, language,
                 negotiated ? api::LanguageChoice::negotiated : api::LanguageChoice::fixed));
  res.set_header(kRequestIdHeader, request_id);
  res.set_header(kNoSniffHeader, "nosniff");
  if (error.retry_after_s > 0) res.set_header("Retry-After", std::to_string(error.retry_after_s));
  metrics_.observe("unmatched", error.method, res.status, 0.0);
  if (access_log_enabled()) {
    log_access(
        {error.method.empty() ? "-" : error.method, instance, res.status, 0.0, request_id, {}});
  }
  return closing_response(res);
}

Reply HttpApp::answer(const HttpRequest& req) {
  Exchange exchange;
  exchange.start = Clock::now();
  exchange.method = req.method;
  exchange.path = req.path;
  metrics_.enter();
  const ReadHeaders headers = read_headers(req);
  exchange.request_id = is_acceptable_request_id(headers.request_id)
                            ? std::string(headers.request_id)
                            : generate_request_id();
  exchange.language = api::preferred_language(headers.accept_language);
  if (access_log_enabled()) exchange.remote = req.remote_ip();

  HttpResponse res;
  // Browsers must not guess a type other than the declared one (a G-code file is not HTML).
  res.set_header(kNoSniffHeader, "nosniff");
  res.set_header(kRequestIdHeader, exchange.request_id);
  cors_.decorate(headers.origin, res);
  try {
    const RouteEntry* route = routes_.find(req.path);
    if (route == nullptr) {
      exchange.write_problem(res,
                             problem(api::ProblemKind::not_found, api::ErrorCode::no_such_resource,
                                     {{"path", problem_instance(req.path)}}));
      return finish(exchange, std::move(res));
    }
    exchange.route = route->path.c_str();
    if (req.method == "OPTIONS") {
      CorsPolicy::answer_options(res, route->allow);
      return finish(exchange, std::move(res));
    }
    if (!RouteTable::allows(*route, req.method)) {
      exchange.write_problem(
          res, problem(api::ProblemKind::method_not_allowed, api::ErrorCode::method_not_allowed,
                       {{"method", req.method}, {"path", route->path}, {"allow", route->allow}}));
      res.set_header("Allow", route->allow);
      return finish(exchange, std::move(res));
    }
    if (route->calculation == nullptr) {
      route->get(req, res);
      return finish(exchange, std::move(res));
    }
    const api::ApiRequest call{route->path,         headers.content_type, req.body,
                               exchange.request_id, headers.accept,       exchange.language};
    if (!route->heavy) {
      write(res, api::run_json_endpoint(call, route->calculation));
      return finish(exchange, std::move(res));
    }
    // On the pool, with the engine's copy of the request.
    const api::JsonHandler handler = route->calculation;
    auto run = [exchange, res, handler](OwnedRequest& owned,
                                        const std::atomic<bool>& stop) mutable {
      const domain::InterruptionScope interruptible(stop);
      const ReadHeaders read = read_headers(owned.request());
      write(res, api::run_json_endpoint(
                     {exchange.route, read.content_type, owned.request().body, exchange.request_id,
                      read.accept, exchange.language, &owned.body_storage()},
                     handler));
      return std::move(res);
    };
    auto settle = [this, exchange, res](DeferredOutcome outcome, HttpResponse computed,
                                        std::string_view failure) mutable {
      return settle_calculation(exchange, std::move(res), outcome, std::move(computed), failure);
    };
    return DeferredResponse{std::move(run), std::move(settle)};
  } catch (const std::exception& e) {
    return internal_error(exchange, e.what());
  }
}

HttpResponse HttpApp::settle_calculation(const Exchange& exchange, HttpResponse res,
                                         DeferredOutcome outcome, HttpResponse computed,
                                         std::string_view failure) {
  switch (outcome) {
    case DeferredOutcome::computed:
      return finish(exchange, std::move(computed));
    case DeferredOutcome::failed:
      return internal_error(exchange, failure);
    case DeferredOutcome::pool_full:
    case DeferredOutcome::over_budget:
    case DeferredOutcome::timed_out:
      exchange.write_problem(
          res,
          problem(api::ProblemKind::unavailable,
                  outcome == DeferredOutcome::pool_full     ? api::ErrorCode::calculations_busy
                  : outcome == DeferredOutcome::over_budget ? api::ErrorCode::memory_busy
                                                            : api::ErrorCode::calculation_timeout,
                  {{"retry_after_s", kBusyRetryAfterSeconds}}));
      res.set_header("Retry-After", std::to_string(kBusyRetryAfterSeconds));
      return finish(exchange, std::move(res));
    case DeferredOutcome::abandoned:
      break;
  }
  // Nothing is sent; the metrics and the log say 499, nginx's "client closed request".
  res.status = kClientClosedRequest;
  return finish(exchange, std::move(res));
}

HttpResponse HttpApp::internal_error(const Exchange& exchange, std::string_view error) {
  spdlog::error("unhandled exception on {} {} (request {}): {}", exchange.method, exchange.path,
                exchange.request_id, error);
  HttpResponse res;
  res.set_header(kNoSniffHeader, "nosniff");
  res.set_header(kRequestIdHeader, exchange.request_id);
  exchange.write_problem(res,
                         problem(api::ProblemKind::internal_error, api::ErrorCode::internal_error));
  return finish(exchange, std::move(res));
}

HttpResponse HttpApp::finish(const Exchange& exchange, HttpResponse res) {
  const double seconds = std::chrono::duration<double>(Clock::now() - exchange.start).count();
  metrics_.leave();
  metrics_.observe(exchange.route, exchange.method, res.status, seconds);
  if (access_log_enabled()) {
    log_access({exchange.method, exchange.path, res.status, seconds * 1000.0, exchange.request_id,
                exchange.remote});
  }
  return res;
}

void HttpApp::install_routes() {
  for (const api::CalculationRoute& route : api::calculation_routes()) {
    routes_.add_calculation(route.path, route.handler, route.heavy);
  }

  routes_.add_get("/healthz", [](const HttpRequest&, HttpResponse& res) {
    reply_json(res, {{"status", "ok"}});
  });

  routes_.add_get("/readyz", [this](const HttpRequest& req, HttpResponse& res) {
    if (req.phase != ServerPhase::serving) {
      write(res, api::problem_response(
                     problem(api::ProblemKind::unavailable, api::ErrorCode::shutting_down),
                     problem_instance(req.path), std::string(res.header(kRequestIdHeader)),
                     api::preferred_language(req.header("Accept-Language"))));
      return;
    }
    reply_json(res, {{"status", "ready"}});
  });

  routes_.add_get("/version", [](const HttpRequest&, HttpResponse& res) {
    reply_json(res, {{"name", "cutcalc"},
                     {"version", build_version()},
                     {"commit", build_commit()},
                     {"build_type", build_type()}});
  });

  routes_.add_get("/metrics", [this](const HttpRequest&, HttpResponse& res) {
    res.set_content(
        metrics_.render() + render_connection_metrics(counters_, engine_->open_connections(),
                                                      engine_->memory_budget()),
        "text/plain; version=0.0.4; charset=utf-8");
  });

  routes_.add_get("/openapi.yaml", [](const HttpRequest&, HttpResponse& res) {
    res.set_content(std::string(embedded_openapi_yaml()), "application/yaml");
  });

  // The calculator page at / and its assets under /ui/ (service/web_assets.h).
  install_web_routes(routes_);
}

}  // namespace cutcalc::service
