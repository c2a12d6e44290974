#include "service/http_app.h"

#include <cctype>
#include <chrono>
#include <exception>
#include <string>

#include <httplib.h>
#include <spdlog/spdlog.h>
#include <nlohmann/json.hpp>

#include "api/accept_header.h"
#include "api/header_text.h"
#include "api/json_endpoint.h"
#include "api/problem.h"
#include "api/routes.h"
#include "service/build_info.h"
#include "service/http_connection.h"
#include "service/http_tuning.h"
#include "service/logging.h"
#include "service/request_id.h"
#include "service/web_assets.h"

namespace cutcalc::service {
namespace {

using Clock = std::chrono::steady_clock;

// What the middleware knows about the request this thread is serving. httplib serves a request
// from its first byte to its access-log callback on one thread, so thread-local state is exact.
struct RequestState {
  Clock::time_point start{};
  const char* route = "unmatched";  // metric label: a known path or "unmatched", never user text
  bool counted_in_flight = false;
  std::string request_id;  // also in the X-Request-Id response header; kept to avoid lookups
};
thread_local RequestState t_request;

constexpr const char* kRequestIdHeader = "X-Request-Id";
constexpr const char* kNoSniffHeader = "X-Content-Type-Options";

void write(httplib::Response& res, api::ApiResponse&& response) {
  res.status = response.status;
  for (const auto& [name, value] : response.headers) {
    // One Vary field: the CORS policy may have set one already (Origin).
    if (name == "Vary") {
      if (const auto said = res.headers.find("Vary"); said != res.headers.end()) {
        said->second += ", " + value;
        continue;
      }
    }
    res.set_header(name, value);
  }
  // As set_content() does (the library has no overload that takes the body by move).
  res.body = std::move(response.body);
  res.set_header("Content-Type", response.content_type);
}

// The request headers cutcalc reads, each the first of its name (as get_header_value() gives),
// found in one pass: the library's lookups compare names through a libc call per character.
struct ReadHeaders {
  std::string_view content_type;
  std::string_view accept;
  std::string_view accept_language;
  std::string_view request_id;
};

ReadHeaders read_headers(const httplib::Request& req) {
  ReadHeaders read;
  bool content_type = false;
  bool accept = false;
  bool accept_language = false;
  bool request_id = false;
  const auto take = [](bool& taken, std::string_view& into, const std::string& value) {
    if (!taken) {
      taken = true;
      into = value;
    }
  };
  for (const auto& [name, value] : req.headers) {
    if (api::iequals_ascii(name, "Content-Type")) {
      take(content_type, read.content_type, value);
    } else if (api::iequals_ascii(name, "Accept")) {
      take(accept, read.accept, value);
    } else if (api::iequals_ascii(name, "Accept-Language")) {
      take(accept_language, read.accept_language, value);
    } else if (api::iequals_ascii(name, kRequestIdHeader)) {
      take(request_id, read.request_id, value);
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

api::Language language_of(const httplib::Request& req) {
  return api::preferred_language(read_headers(req).accept_language);
}

void write_problem(const httplib::Request& req, httplib::Response& res,
                   const api::Problem& problem) {
  write(res, api::problem_response(problem, problem_instance(req.path),
                                   res.get_header_value(kRequestIdHeader), language_of(req)));
}

api::Problem problem(api::ProblemKind kind, api::ErrorCode code,
                     nlohmann::json params = nlohmann::json::object()) {
  return {kind, api::Message{code, std::move(params)}, {}};
}

// Problems for statuses the HTTP library sets by itself, before any handler runs.
api::Problem library_problem(const httplib::Request& req, int status) {
  switch (status) {
    case 404:
      return problem(api::ProblemKind::not_found, api::ErrorCode::no_such_resource,
                     {{"path", problem_instance(req.path)}});
    case 413:
      return problem(api::ProblemKind::payload_too_large, api::ErrorCode::body_too_large);
    default:
      return problem(api::ProblemKind::bad_request, api::ErrorCode::malformed_http,
                     {{"reason", "status " + std::to_string(status)}});
  }
}

void reply_json(httplib::Response& res, const nlohmann::json& body) {
  res.status = 200;
  res.set_content(body.dump(), "application/json");
}

}  // namespace

HttpApp::HttpApp(Config config)
    : config_(std::move(config)),
      server_(std::make_unique<TunedServer>(
          config_.http, [this](const EngineError& error) { return engine_error_response(error); })),
      cors_(config_.cors_origins) {
  install_middleware();
  install_routes();
}

HttpApp::~HttpApp() = default;

int HttpApp::bind() {
  return bind_with_backlog(*server_, config_.host.c_str(), config_.port,
                           config_.http.listen_backlog);
}

bool HttpApp::serve() {
  const bool served = server_->listen_after_bind();
  // The listener is closed; answer what is in flight before the caller tears the app down.
  const auto limit = std::max(config_.http.limits.request_timeout, std::chrono::milliseconds{1000});
  if (!server_->drain(limit)) {
    spdlog::warn("shutdown: requests still in flight after {} ms were dropped", limit.count());
  }
  return served;
}

void HttpApp::shutdown() {
  draining_.store(true);
  server_->stop();
}

void HttpApp::serve_connection(int sock) { server_->adopt_connection(sock); }

std::string HttpApp::engine_error_response(const EngineError& error) {
  // The head could not be trusted, so its Accept-Language is not read: these answer in English.
  const api::Problem said =
      error.status == 413
          ? problem(api::ProblemKind::payload_too_large, api::ErrorCode::body_too_large)
      : error.status == 503
          ? problem(api::ProblemKind::unavailable, api::ErrorCode::connection_limit)
          : problem(api::ProblemKind::bad_request, api::ErrorCode::malformed_http,
                    {{"reason", std::string(error.detail)}});
  const std::string request_id = generate_request_id();
  const std::string instance = problem_instance(error.target);
  const api::ApiResponse problem = api::problem_response(
      said, instance, request_id, api::Language::en, api::LanguageChoice::fixed);
  metrics_.observe("unmatched", error.method, problem.status, 0.0);
  if (access_log_enabled()) {
    log_access(
        {error.method.empty() ? "-" : error.method, instance, problem.status, 0.0, request_id, {}});
  }
  httplib::Headers headers = cors_.rejection_headers(error.origin);
  headers.insert(problem.headers.begin(), problem.headers.end());
  headers.emplace(kRequestIdHeader, request_id);
  headers.emplace(kNoSniffHeader, "nosniff");
  return closing_response(problem.status, problem.content_type, problem.body, headers);
}

void HttpApp::install_middleware() {
  server_->set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    t_request.start = Clock::now();
    t_request.route = "unmatched";
    t_request.counted_in_flight = true;
    metrics_.enter();
    // Browsers must not guess a type other than the declared one (a G-code file is not HTML).
    // Set per response: the library's set_default_headers() broke every response of the -O3
    // build against Debian's libcpp-httplib 0.11.4 (empty replies), while the ASan build worked.
    res.set_header(kNoSniffHeader, "nosniff");
    const ReadHeaders headers = read_headers(req);
    if (is_acceptable_request_id(headers.request_id)) {
      t_request.request_id = headers.request_id;
    } else {
      t_request.request_id = generate_request_id();
    }
    res.set_header(kRequestIdHeader, t_request.request_id);

    // Once per response, whatever answers it (set_header appends, so a second call repeats them).
    cors_.decorate(req, res);
    const RouteEntry* route = routes_.find(req.path);
    if (route == nullptr) {
      write_problem(req, res,
                    problem(api::ProblemKind::not_found, api::ErrorCode::no_such_resource,
                            {{"path", problem_instance(req.path)}}));
      return httplib::Server::HandlerResponse::Handled;
    }
    t_request.route = route->path.c_str();
    if (req.method == "OPTIONS") {
      CorsPolicy::answer_options(res, route->allow);
      return httplib::Server::HandlerResponse::Handled;
    }
    if (!RouteTable::allows(*route, req.method)) {
      write_problem(
          req, res,
          problem(api::ProblemKind::method_not_allowed, api::ErrorCode::method_not_allowed,
                  {{"method", req.method}, {"path", route->path}, {"allow", route->allow}}));
      res.set_header("Allow", route->allow);
      return httplib::Server::HandlerResponse::Handled;
    }
    if (route->calculation != nullptr) {
      // Answered here, from the body the engine framed: the library would otherwise match every
      // route's regex and copy the body first.
      write(res, api::run_json_endpoint(
                     {req.path, headers.content_type, framed_request_body(), t_request.request_id,
                      headers.accept, api::preferred_language(headers.accept_language)},
                     route->calculation));
      return httplib::Server::HandlerResponse::Handled;
    }
    return httplib::Server::HandlerResponse::Unhandled;
  });

  // Statuses set by the library itself (body too large, malformed request line) get a problem
  // body too; responses that already have a body are ours and are left alone.
  server_->set_error_handler(
      httplib::Server::HandlerWithResponse([](const httplib::Request& req, httplib::Response& res) {
        if (!res.body.empty()) {
          return httplib::Server::HandlerResponse::Unhandled;
        }
        if (!res.has_header(kNoSniffHeader)) {
          res.set_header(kNoSniffHeader, "nosniff");
        }
        if (!res.has_header(kRequestIdHeader)) {
          res.set_header(kRequestIdHeader, generate_request_id());
        }
        write_problem(req, res, library_problem(req, res.status));
        return httplib::Server::HandlerResponse::Handled;
      }));

  server_->set_exception_handler(
      [](const httplib::Request& req, httplib::Response& res, std::exception_ptr error) {
        std::string what = "unknown exception";
        try {
          std::rethrow_exception(std::move(error));
        } catch (const std::exception& e) {
          what = e.what();
        } catch (...) {
        }
        spdlog::error("unhandled exception on {} {} (request {}): {}", req.method, req.path,
                      res.get_header_value(kRequestIdHeader), what);
        write_problem(req, res,
                      problem(api::ProblemKind::internal_error, api::ErrorCode::internal_error));
      });

  server_->set_logger([this](const httplib::Request& req, const httplib::Response& res) {
    const double seconds =
        t_request.counted_in_flight
            ? std::chrono::duration<double>(Clock::now() - t_request.start).count()
            : 0.0;
    if (t_request.counted_in_flight) {
      metrics_.leave();
    }
    metrics_.observe(t_request.route, req.method, res.status, seconds);
    if (access_log_enabled()) {
      log_access({req.method, req.path, res.status, seconds * 1000.0,
                  res.get_header_value(kRequestIdHeader), req.remote_addr});
    }
    t_request.route = "unmatched";
    t_request.counted_in_flight = false;
  });
}

void HttpApp::install_routes() {
  // Calculations are answered at routing (install_middleware); the library only serves the rest.
  for (const api::CalculationRoute& route : api::calculation_routes()) {
    routes_.add_calculation(route.path, route.handler);
  }

  routes_.add("/healthz", RouteMethod::get);
  server_->Get("/healthz", [](const httplib::Request&, httplib::Response& res) {
    reply_json(res, {{"status", "ok"}});
  });

  routes_.add("/readyz", RouteMethod::get);
  server_->Get("/readyz", [this](const httplib::Request& req, httplib::Response& res) {
    if (draining_.load()) {
      write_problem(req, res,
                    problem(api::ProblemKind::unavailable, api::ErrorCode::shutting_down));
      return;
    }
    reply_json(res, {{"status", "ready"}});
  });

  routes_.add("/version", RouteMethod::get);
  server_->Get("/version", [](const httplib::Request&, httplib::Response& res) {
    reply_json(res, {{"name", "cutcalc"},
                     {"version", build_version()},
                     {"commit", build_commit()},
                     {"build_type", build_type()}});
  });

  routes_.add("/metrics", RouteMethod::get);
  server_->Get("/metrics", [this](const httplib::Request&, httplib::Response& res) {
    res.set_content(metrics_.render() +
                        render_connection_metrics(server_->counters(), server_->open_connections()),
                    "text/plain; version=0.0.4; charset=utf-8");
  });

  routes_.add("/openapi.yaml", RouteMethod::get);
  server_->Get("/openapi.yaml", [](const httplib::Request&, httplib::Response& res) {
    const std::string_view yaml = embedded_openapi_yaml();
    res.set_content(yaml.data(), yaml.size(), "application/yaml");
  });

  // The calculator page at / and its assets under /ui/ (service/web_assets.h).
  install_web_routes(*server_, routes_);
}

}  // namespace cutcalc::service
