// Bare JSON echo: POST <any path> answers 200 with the request body as application/json. By
// default cutcalc's own HTTP engine, listener and tuning with an echo in place of the app, so the
// benchmark can tell the cost of cutcalc's own work from the cost of the HTTP layer. Other modes
// run cpp-httplib's server, to measure what the engine does:
//   --mode tuned    cutcalc's Listener + EventLoopEngine (as cutcalc; default)
//   --mode setters  httplib::Server with cutcalc's runtime settings through its setters (the
//                   library's own connection loop and fixed thread pool)
//   --mode untuned  httplib::Server with the library's compiled-in defaults (only an explicit
//                   --nodelay is applied, to isolate its effect)
// usage: httplib_echo [--host H] [--port P] [--threads N] [--backlog N] [--nodelay 0|1]
//                     [--keep-alive-max N] [--mode tuned|setters|untuned] [--log-level L (ignored)]
// (--threads: the engine's event loops in tuned mode.)
// Prints "listening on H:P" once bound; SIGINT/SIGTERM stop it cleanly.

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <thread>

#include <httplib.h>

#include "service/http_tuning.h"
#include "service/listener.h"

namespace {

struct Options {
  std::string host = "127.0.0.1";
  int port = 0;
  std::string mode = "tuned";
  bool nodelay_given = false;  // --mode untuned honours an explicit --nodelay, nothing else
  cutcalc::service::HttpTuning tuning;
};

bool parse_size(const char* text, std::size_t& out) {
  char* end = nullptr;
  const long long value = std::strtoll(text, &end, 10);
  if (end == text || *end != '\0' || value < 0) return false;
  out = static_cast<std::size_t>(value);
  return true;
}

bool parse(int argc, char** argv, Options& options) {
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (i + 1 >= argc) return false;
    const char* value = argv[++i];
    std::size_t number = 0;
    if (flag == "--host") {
      options.host = value;
    } else if (flag == "--log-level") {
      // accepted and ignored, so the echo can stand in for cutcalc in bench/http_bench.sh
    } else if (flag == "--mode") {
      options.mode = value;
      if (options.mode != "tuned" && options.mode != "setters" && options.mode != "untuned") {
        return false;
      }
    } else if (!parse_size(value, number)) {
      return false;
    } else if (flag == "--port") {
      options.port = static_cast<int>(number);
    } else if (flag == "--threads") {
      options.tuning.event_loop_threads = number;
    } else if (flag == "--backlog") {
      options.tuning.listen_backlog = static_cast<int>(number);
    } else if (flag == "--nodelay") {
      options.tuning.tcp_nodelay = number != 0;
      options.nodelay_given = true;
    } else if (flag == "--keep-alive-max") {
      options.tuning.keep_alive_max_requests = number;
    } else {
      return false;
    }
  }
  return true;
}

int serve_with_engine(const Options& options, sigset_t stop_signals) {
  using namespace cutcalc::service;
  Listener listener;
  const int port = listener.open(
      {options.host, options.port, options.tuning.listen_backlog, options.tuning.reuse_port});
  if (port < 0) {
    std::fprintf(stderr, "httplib_echo: cannot bind %s:%d: %s\n", options.host.c_str(),
                 options.port, listener.error().c_str());
    return 1;
  }
  ConnectionCounters counters;
  EventLoopEngine engine(
      event_loop_settings(options.tuning),
      [](const HttpRequest& request) -> Reply {
        HttpResponse response;
        response.set_content(std::string(request.body), "application/json");
        return response;
      },
      [](const EngineError& error) {
        HttpResponse response;
        response.status = http_status(error.fault);
        return closing_response(response);
      },
      [&listener] { return listener.stopped() ? ServerPhase::stopped : ServerPhase::serving; },
      counters);
  std::thread stopper([&listener, stop_signals] {
    int signal_number = 0;
    sigwait(&stop_signals, &signal_number);
    listener.stop();
  });
  std::printf("listening on %s:%d (mode tuned)\n", options.host.c_str(), port);
  std::fflush(stdout);
  const bool ok = listener.run([&engine](int sock) { engine.adopt(sock); });
  if (!listener.stopped()) kill(getpid(), SIGTERM);  // the listener failed: free the stopper
  stopper.join();
  engine.drain(std::chrono::milliseconds(1000));
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (!parse(argc, argv, options)) {
    std::fprintf(stderr,
                 "usage: httplib_echo [--host H] [--port P] [--threads N] [--backlog N]"
                 " [--nodelay 0|1] [--keep-alive-max N] [--mode tuned|setters|untuned]\n");
    return 2;
  }

  // Signals go to a dedicated thread that stops the server (stop() is not async-signal-safe).
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

  if (options.mode == "tuned") return serve_with_engine(options, stop_signals);

  httplib::Server server;
  server.Post(".*", [](const httplib::Request& request, httplib::Response& response) {
    response.set_content(request.body, "application/json");
  });
  if (options.mode == "setters") {
    server.set_keep_alive_max_count(options.tuning.keep_alive_max_requests);
    server.set_keep_alive_timeout(options.tuning.limits.keep_alive_timeout.count());
    server.set_payload_max_length(options.tuning.limits.max_body_bytes);
    server.set_tcp_nodelay(options.tuning.tcp_nodelay);
  } else if (options.nodelay_given) {
    server.set_tcp_nodelay(options.tuning.tcp_nodelay);
  }
  const int port = options.port == 0
                       ? server.bind_to_any_port(options.host)
                       : (server.bind_to_port(options.host, options.port) ? options.port : -1);
  if (port < 0) {
    std::fprintf(stderr, "httplib_echo: cannot bind %s:%d\n", options.host.c_str(), options.port);
    return 1;
  }

  std::atomic<bool> finished{false};
  std::thread stopper([&server, &finished, stop_signals] {
    int signal_number = 0;
    sigwait(&stop_signals, &signal_number);
    if (!finished) server.stop();
  });

  std::printf("listening on %s:%d (mode %s)\n", options.host.c_str(), port, options.mode.c_str());
  std::fflush(stdout);
  const bool ok = server.listen_after_bind();
  // If the listener ended on its own, wake the stopper so it can be joined (a signal sent
  // while every thread blocks it stays pending and does no harm).
  finished = true;
  kill(getpid(), SIGTERM);
  stopper.join();
  return ok ? 0 : 1;
}
