#include "service/http_event_loop.h"

#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/epoll.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <mutex>
#include <system_error>
#include <thread>
#include <unordered_map>
#include <utility>

namespace cutcalc::service {
namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

// Deadlines (keep-alive, request) and server stop are checked this often.
constexpr milliseconds kSweepInterval{200};

constexpr char kServiceUnavailable[] =
    "HTTP/1.1 503 Service Unavailable\r\nConnection: close\r\nContent-Length: 0\r\n\r\n";

}  // namespace

struct EventLoopEngine::Connection {
  Connection(int sock, const EventLoopSettings& settings, std::atomic<std::size_t>& open)
      : fd(sock),
        stream(sock, settings.read_timeout, settings.write_timeout),
        requests_left(std::max<std::size_t>(settings.keep_alive_max_requests, 1)),
        open_connections(open) {
    open_connections.fetch_add(1);
  }
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;
  ~Connection() {
    ::shutdown(fd, SHUT_RDWR);
    ::close(fd);
    open_connections.fetch_sub(1);
  }

  int fd;
  ConnectionStream stream;
  std::size_t requests_left;
  std::size_t loop = 0;
  std::atomic<std::size_t>& open_connections;  // the engine's count, for drain()
  bool in_request = false;                     // some bytes of the next request are buffered
  bool close_after_flush = false;              // the response being flushed is the last one
  Clock::time_point deadline{};                // of the request in progress, or of the idle wait
};

class EventLoopEngine::Loop {
 public:
  Loop(EventLoopEngine& engine) : engine_(engine) {
    epoll_fd_ = ::epoll_create1(EPOLL_CLOEXEC);
    wake_fd_ = ::eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK);
    if (epoll_fd_ < 0 || wake_fd_ < 0) {
      close_fds();
      throw std::system_error(errno, std::generic_category(), "event loop");
    }
    epoll_event event{};
    event.events = EPOLLIN;
    event.data.ptr = nullptr;  // the wake-up eventfd
    ::epoll_ctl(epoll_fd_, EPOLL_CTL_ADD, wake_fd_, &event);
    thread_ = std::thread([this] { run(); });
  }
  Loop(const Loop&) = delete;
  Loop& operator=(const Loop&) = delete;
  ~Loop() {
    {
      const std::lock_guard lock(inbox_mutex_);
      quit_ = true;
    }
    wake();
    thread_.join();
    close_fds();
  }

  // From any thread: the loop takes the connection over (and serves what it has buffered).
  void post(std::shared_ptr<Connection> connection) {
    bool was_empty = false;
    {
      const std::lock_guard lock(inbox_mutex_);
      if (quit_) return;  // dropping it closes it
      was_empty = inbox_.empty();
      inbox_.push_back(std::move(connection));
    }
    if (was_empty) wake();  // otherwise a wake-up is already pending
  }

 private:
  void wake() {
    const std::uint64_t one = 1;
    [[maybe_unused]] const auto n = ::write(wake_fd_, &one, sizeof(one));
  }

  void close_fds() {
    if (wake_fd_ >= 0) ::close(wake_fd_);
    if (epoll_fd_ >= 0) ::close(epoll_fd_);
  }

  void run() {
    std::array<epoll_event, 256> events{};
    auto next_sweep = Clock::now() + kSweepInterval;
    for (;;) {
      const auto wait = std::chrono::duration_cast<milliseconds>(next_sweep - Clock::now());
      const int n =
          ::epoll_wait(epoll_fd_, events.data(), static_cast<int>(events.size()),
                       static_cast<int>(std::clamp<milliseconds::rep>(wait.count(), 0, 1000)));
      for (int i = 0; i < n; ++i) {
        auto* connection = static_cast<Connection*>(events[static_cast<std::size_t>(i)].data.ptr);
        if (connection == nullptr) {
          if (!take_inbox()) return finish();
          continue;
        }
        try {
          on_readable(connection);
        } catch (...) {  // e.g. bad_alloc: lose this connection, not the loop
          drop(connection);
        }
      }
      const auto now = Clock::now();
      if (now >= next_sweep || (engine_.stopping_() && !connections_.empty())) {
        sweep(now);
        next_sweep = now + kSweepInterval;
      }
    }
  }

  // False when the loop is to quit.
  bool take_inbox() {
    std::uint64_t count = 0;
    [[maybe_unused]] const auto n = ::read(wake_fd_, &count, sizeof(count));
    std::vector<std::shared_ptr<Connection>> arrived;
    {
      const std::lock_guard lock(inbox_mutex_);
      if (quit_) return false;
      arrived.swap(inbox_);
    }
    for (auto& connection : arrived) {
      // Also while stopping: the connection may carry a request in flight; the sweep closes it
      // if it is idle.
      epoll_event event{};
      event.events = EPOLLIN | EPOLLRDHUP;
      event.data.ptr = connection.get();
      if (::epoll_ctl(epoll_fd_, EPOLL_CTL_ADD, connection->fd, &event) != 0) continue;
      Connection* raw = connection.get();
      connections_.emplace(raw, std::move(connection));
      if (raw->stream.has_buffered_input()) after_input(raw, false);
    }
    return true;
  }

  void finish() {
    connections_.clear();
    const std::lock_guard lock(inbox_mutex_);
    inbox_.clear();
  }

  void on_readable(Connection* connection) {
    const std::size_t limit = kMaxBufferedHead + engine_.settings_.max_body_bytes;
    switch (connection->stream.fill_nonblocking(limit)) {
      case ConnectionStream::Fill::data:
        after_input(connection, false);
        return;
      case ConnectionStream::Fill::full:
        after_input(connection, false, true);
        return;
      case ConnectionStream::Fill::eof:
        after_input(connection, true);
        return;
      case ConnectionStream::Fill::again:
        return;
      case ConnectionStream::Fill::error:
        drop(connection);
        return;
    }
  }

  void after_input(Connection* connection, bool eof, bool buffer_full = false) {
    const auto now = Clock::now();
    auto outcome = engine_.serve_nonblocking(*connection);
    // Cannot happen (the buffer holds any head + body the fast path accepts), but never spin on
    // a full buffer: let a blocking thread read on.
    if (outcome == Outcome::wait_input && buffer_full) outcome = Outcome::to_thread;
    switch (outcome) {
      case Outcome::idle:
        if (eof) return drop(connection);
        connection->in_request = false;
        connection->deadline = now + engine_.settings_.keep_alive_timeout;
        connection->stream.release_idle_buffers();
        return;
      case Outcome::wait_input:
        if (eof) return drop(connection);  // closed in the middle of a request
        if (!connection->in_request) {
          connection->in_request = true;
          connection->deadline = engine_.settings_.request_timeout.count() > 0
                                     ? now + engine_.settings_.request_timeout
                                     : Clock::time_point::max();
        }
        return;
      case Outcome::to_thread: {
        if (!connection->in_request) {
          connection->in_request = true;
          connection->deadline = engine_.settings_.request_timeout.count() > 0
                                     ? now + engine_.settings_.request_timeout
                                     : Clock::time_point::max();
        }
        ::epoll_ctl(epoll_fd_, EPOLL_CTL_DEL, connection->fd, nullptr);
        const auto it = connections_.find(connection);
        auto owned = std::move(it->second);
        connections_.erase(it);
        engine_.hand_to_thread(std::move(owned));
        return;
      }
      case Outcome::close:
        return drop(connection);
    }
  }

  void drop(Connection* connection) { connections_.erase(connection); }  // closes it

  void sweep(Clock::time_point now) {
    const bool stopping = engine_.stopping_();
    for (auto it = connections_.begin(); it != connections_.end();) {
      Connection& connection = *it->second;
      // Stopping closes idle connections; a request in flight keeps its connection until it
      // is answered (the response then says Connection: close) or its deadline passes.
      if ((stopping && !connection.in_request) || now >= connection.deadline) {
        if (connection.in_request) {
          engine_.counters_.request_timeouts.fetch_add(1, std::memory_order_relaxed);
        }
        it = connections_.erase(it);
      } else {
        ++it;
      }
    }
  }

  EventLoopEngine& engine_;
  int epoll_fd_ = -1;
  int wake_fd_ = -1;
  std::mutex inbox_mutex_;
  std::vector<std::shared_ptr<Connection>> inbox_;
  bool quit_ = false;  // guarded by inbox_mutex_
  std::unordered_map<Connection*, std::shared_ptr<Connection>> connections_;  // loop thread only
  std::thread thread_;
};

EventLoopEngine::EventLoopEngine(EventLoopSettings settings, ServeRequest serve, Stopping stopping,
                                 ConnectionCounters& counters, std::shared_ptr<PoolLoad> load)
    : settings_(std::move(settings)),
      serve_(std::move(serve)),
      stopping_(std::move(stopping)),
      counters_(counters),
      pool_(std::make_unique<ElasticThreadPool>(settings_.blocking_threads, std::move(load))) {
  const std::size_t loops = std::max<std::size_t>(settings_.loops, 1);
  for (std::size_t i = 0; i < loops; ++i) loops_.push_back(std::make_unique<Loop>(*this));
}

bool EventLoopEngine::drain(std::chrono::milliseconds limit) {
  const auto until = Clock::now() + limit;
  while (open_connections_.load() > 0) {
    if (Clock::now() >= until) {
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return true;
}

EventLoopEngine::~EventLoopEngine() {
  pool_->shutdown();  // blocking work finishes first; it may still park connections on the loops
  loops_.clear();
}

void EventLoopEngine::adopt(int sock) {
  counters_.connections.fetch_add(1, std::memory_order_relaxed);
  if (settings_.tcp_nodelay) {
    const int on = 1;
    ::setsockopt(sock, IPPROTO_TCP, TCP_NODELAY, &on, sizeof(on));
  }
  std::shared_ptr<Connection> connection;
  try {
    connection = std::make_shared<Connection>(sock, settings_, open_connections_);
  } catch (...) {
    ::close(sock);
    return;
  }
  connection->loop = next_loop_.fetch_add(1, std::memory_order_relaxed) % loops_.size();
  // Like httplib, the first request may take the keep-alive timeout to start.
  connection->deadline = Clock::now() + settings_.keep_alive_timeout;
  park(std::move(connection));
}

void EventLoopEngine::park(std::shared_ptr<Connection> connection) {
  Loop& loop = *loops_[connection->loop];
  loop.post(std::move(connection));
}

EventLoopEngine::Outcome EventLoopEngine::serve_nonblocking(Connection& connection) {
  ConnectionStream& stream = connection.stream;
  for (;;) {
    if (!stream.has_buffered_input()) return Outcome::idle;
    switch (classify_request(stream.buffered_input(), settings_.max_body_bytes)) {
      case RequestReadiness::incomplete:
        return Outcome::wait_input;
      case RequestReadiness::needs_thread:
        return Outcome::to_thread;
      case RequestReadiness::complete:
        break;
    }
    stream.set_nonblocking_only(true);
    stream.start_request(Clock::time_point::max());
    // A request that arrived before the stop is answered, and is the connection's last.
    const bool close_connection = connection.requests_left <= 1 || stopping_();
    bool connection_closed = false;
    bool ok = false;
    try {
      ok = serve_(stream, close_connection, connection_closed);
    } catch (...) {
      // httplib catches handler exceptions; anything else ends the connection.
      return Outcome::close;
    }
    stream.set_nonblocking_only(false);
    if (connection.requests_left > 1) --connection.requests_left;
    connection.in_request = false;
    counters_.requests.fetch_add(1, std::memory_order_relaxed);
    const bool last = !ok || connection_closed || close_connection;
    switch (stream.flush_nonblocking()) {
      case ConnectionStream::Flush::error:
        return Outcome::close;
      case ConnectionStream::Flush::again:
        connection.close_after_flush = last;
        return Outcome::to_thread;
      case ConnectionStream::Flush::done:
        if (last) return Outcome::close;
        break;
    }
  }
}

bool EventLoopEngine::hand_to_thread(std::shared_ptr<Connection> connection) {
  counters_.blocking_handoffs.fetch_add(1, std::memory_order_relaxed);
  const bool responding = connection->stream.has_pending_output();
  std::function<void()> task = [this, connection] { serve_blocking(connection); };
  if (pool_->try_enqueue(task)) return true;
  // At the thread cap with a full queue: refuse this request rather than wait.
  counters_.rejected_at_cap.fetch_add(1, std::memory_order_relaxed);
  if (!responding) {
    [[maybe_unused]] const auto n =
        ::send(connection->fd, kServiceUnavailable, sizeof(kServiceUnavailable) - 1,
               MSG_NOSIGNAL | MSG_DONTWAIT);
  }
  return false;  // `connection` (and the task's copy) drop here: closed
}

void EventLoopEngine::serve_blocking(const std::shared_ptr<Connection>& connection) {
  ConnectionStream& stream = connection->stream;
  stream.set_nonblocking_only(false);
  if (stream.has_pending_output()) {
    if (!stream.flush() || connection->close_after_flush) return;  // closed with the last copy
  }
  if (stream.has_buffered_input()) {
    // A request has begun that needs blocking reads: serve it as stock httplib would, within
    // the deadline set when its first bytes arrived.
    stream.start_request(connection->in_request ? connection->deadline
                         : settings_.request_timeout.count() > 0
                             ? Clock::now() + settings_.request_timeout
                             : Clock::time_point::max());
    const bool close_connection = connection->requests_left <= 1 || stopping_();
    bool connection_closed = false;
    bool ok = false;
    try {
      ok = serve_(stream, close_connection, connection_closed);
    } catch (...) {
      return;  // closed with the last copy
    }
    if (connection->requests_left > 1) --connection->requests_left;
    connection->in_request = false;
    counters_.requests.fetch_add(1, std::memory_order_relaxed);
    if (stream.timed_out()) {
      counters_.request_timeouts.fetch_add(1, std::memory_order_relaxed);
      stream.flush();
      return;
    }
    if (!stream.flush() || !ok || connection_closed || close_connection) return;
  }
  // Back to the loop for the next request (or for what is already buffered).
  connection->deadline = Clock::now() + settings_.keep_alive_timeout;
  park(connection);
}

}  // namespace cutcalc::service
