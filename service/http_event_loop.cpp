#include "service/http_event_loop.h"

#include <linux/sockios.h>
#include <malloc.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/epoll.h>
#include <sys/eventfd.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <mutex>
#include <optional>
#include <system_error>
#include <thread>
#include <unordered_map>
#include <utility>

#include "service/unique_fd.h"

namespace cutcalc::service {
namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

// Deadlines and server stop are checked this often.
constexpr milliseconds kSweepInterval{200};
// Buffers of an idle connection above this size are given back.
constexpr std::size_t kIdleBufferBytes = 16 * 1024;
constexpr std::size_t kReadChunk = 16 * 1024;
constexpr std::uint64_t kTrimAfterReleasedBytes = 4 * 1024 * 1024;
constexpr char kContinue[] = "HTTP/1.1 100 Continue\r\n\r\n";
// A body written as it is sent is asked for this much at a time, once the last piece has gone to
// the socket: what one such response holds is its source's state and about one piece.
constexpr std::size_t kBodyPieceBytes = 64 * 1024;

}  // namespace

// Members of EventLoopEngine::Connection: their types have this file's name on them instead of an
// anonymous namespace, since a class with external linkage must not hold internal types
// (-Wsubobject-linkage, which unity builds raise).
namespace event_loop_detail {

// Counts a connection as open from its first member's construction to its last member's
// destruction, so that drain() sees it closed only once its descriptor is.
class OpenCount {
 public:
  explicit OpenCount(std::atomic<std::size_t>& count) : count_(count) { count_.fetch_add(1); }
  OpenCount(const OpenCount&) = delete;
  OpenCount& operator=(const OpenCount&) = delete;
  ~OpenCount() { count_.fetch_sub(1); }

 private:
  std::atomic<std::size_t>& count_;
};

// One of the engine's places for a body above the default limit (HttpLimits::max_large_bodies):
// held from the head of such a request until it is answered or its connection goes.
class LargeBodySlot {
 public:
  LargeBodySlot() = default;
  LargeBodySlot(const LargeBodySlot&) = delete;
  LargeBodySlot& operator=(const LargeBodySlot&) = delete;
  ~LargeBodySlot() { release(); }

  [[nodiscard]] bool held() const { return count_ != nullptr; }
  bool acquire(std::atomic<std::uint64_t>& count, std::size_t limit) {
    std::uint64_t now = count.load();
    do {
      if (now >= limit) return false;
    } while (!count.compare_exchange_weak(now, now + 1));
    count_ = &count;
    return true;
  }
  void release() {
    if (count_ != nullptr) count_->fetch_sub(1);
    count_ = nullptr;
  }

 private:
  std::atomic<std::uint64_t>* count_ = nullptr;
};

// What a connection waits for between two events. Each state has one deadline, set as it is
// entered, and one epoll interest (`interest`); the sweep's action at the deadline is the state's.
enum class Wait {
  idle,         // the next request: keep_alive_timeout from the last response
  request,      // the rest of a request: request_timeout from its first byte (and a large body's
                // transfer time); past it the connection closes
  calculation,  // the pool's answer to its request: calculation_timeout; past it 503
  piece,        // the pool's next piece of a body being sent: calculation_timeout
  output,       // the socket to take the output: write_timeout, renewed while the client reads
  linger        // the client's end after the last response: linger_time
};

constexpr std::uint32_t interest(Wait state) {
  switch (state) {
    case Wait::idle:
    case Wait::request:
    case Wait::linger:  // read and dropped
      return EPOLLIN;
    case Wait::calculation:  // only the client's going is news, its end of input included
      return EPOLLRDHUP;
    case Wait::piece:  // only a failed socket (EPOLLHUP, EPOLLERR: always reported)
      return 0;
    case Wait::output:
      return EPOLLOUT;
  }
  return EPOLLIN;
}

// A request partly received.
struct Receiving {
  Clock::time_point deadline;  // when all of it must be in
  bool continue_sent = false;  // 100 Continue was sent for it
};

// A request handed to the calculation pool, owned by its connection until it is answered.
struct AwaitedCalculation {
  // How it is settled, and the flag that stops its calculation (shared with the job).
  std::function<HttpResponse(DeferredOutcome, HttpResponse, std::string_view)> settle;
  std::shared_ptr<std::atomic<bool>> stop;
  Clock::time_point deadline;  // answered 503 if the pool has not answered by then
  bool head_only = false;
  bool http11 = true;
  ConnectionAfter after = ConnectionAfter::close;
};

// The body of the response being sent, written as it is sent.
struct StreamedBody {
  std::shared_ptr<domain::TextSource> source;
  bool chunked = true;         // HTTP/1.1; HTTP/1.0 ends it by the close
  std::size_t held_bytes = 0;  // what the source holds, as of its last piece
};

}  // namespace event_loop_detail

namespace {

using event_loop_detail::AwaitedCalculation;
using event_loop_detail::LargeBodySlot;
using event_loop_detail::OpenCount;
using event_loop_detail::Receiving;
using event_loop_detail::StreamedBody;
using event_loop_detail::Wait;

constexpr int kLargeBodyRetryAfterSeconds = 1;

}  // namespace

struct EventLoopEngine::Connection {
  Connection(UniqueFd socket, std::uint64_t connection_id, std::size_t requests,
             std::atomic<std::size_t>& open, MemoryBudget& budget)
      : counted(open),
        charge(budget),
        fd(std::move(socket)),
        id(connection_id),
        addresses(fd.get()),
        requests_left(requests) {}

  [[nodiscard]] std::string_view unread() const {
    return {input.data() + input_begin, input_end - input_begin};
  }
  void consume(std::size_t bytes) {
    input_begin += bytes;
    if (input_begin == input_end) input_begin = input_end = 0;
  }
  void drop_input() { input_begin = input_end = 0; }
  [[nodiscard]] bool has_output() const { return output_offset < output.size(); }
  [[nodiscard]] std::size_t pending_output() const { return output.size() - output_offset; }

  OpenCount counted;  // first: released last
  // What the connection holds in the memory budget: its large body (from its admission until its
  // calculation has answered: the pool's job holds a copy) and the output not yet sent.
  BudgetCharge charge;
  std::uint64_t body_charge = 0;
  UniqueFd fd;
  std::uint64_t id;  // unique in the engine's life: a completion for a reused descriptor is stale
  SocketAddresses addresses;
  // Bytes read: [input_begin, input_end) not yet consumed. Grown, never zero-filled per read.
  std::vector<char> input;
  std::size_t input_begin = 0;
  std::size_t input_end = 0;
  std::string output;  // responses; [output_offset, size) not yet sent
  std::size_t output_offset = 0;
  // The request being parsed: its fields, a chunked body decoded, a percent-decoded path.
  std::vector<HeaderField> fields;
  std::string decoded_body;
  std::string path_scratch;
  std::size_t requests_left;
  // A request with a large body (a program to time): its place, the input it may buffer (0: the
  // default), and how much must be buffered before framing it again is worth it (a 32 MiB body
  // arrives in thousands of reads; framing it after each would cost quadratic time).
  LargeBodySlot large_body;
  std::size_t buffer_limit = 0;
  std::size_t frame_again_at = 0;

  // What it waits for now, until when (Loop::wait sets both, and the epoll interest).
  Wait waiting = Wait::idle;
  Clock::time_point deadline{};
  std::uint32_t events = 0;  // the epoll interest registered
  // What it holds besides its buffers: a request partly in, a request on the pool, a body being
  // sent. Each is owned here and gone once done.
  std::optional<Receiving> receiving;
  std::optional<AwaitedCalculation> awaited;
  std::optional<StreamedBody> streamed;
  bool peer_eof = false;            // the client will send nothing more
  bool close_after_output = false;  // the last response is in the output
  // Bytes the socket had not sent when the connection began waiting for its client to read (the
  // write timeout then runs from each wait in which the client read enough).
  std::size_t socket_queued = 0;
  Clock::time_point idle_since{};  // when its last response was sent

  // Gives back the buffers of an idle connection (a few KiB of its own each; thousands of idle
  // keep-alive connections must cost little).
  void release_buffers() {
    std::vector<char>().swap(input);
    input_begin = input_end = 0;
    std::string().swap(output);
    output_offset = 0;
    std::vector<HeaderField>().swap(fields);
    std::string().swap(decoded_body);
    std::string().swap(path_scratch);
  }
  [[nodiscard]] std::uint64_t held_bytes() const {
    return input.capacity() + output.capacity() + fields.capacity() * sizeof(HeaderField) +
           decoded_body.capacity() + path_scratch.capacity();
  }
};

// A response computed on the pool, addressed to the connection that asked for it.
struct EventLoopEngine::Completion {
  int fd = -1;
  std::uint64_t connection_id = 0;
  HttpResponse response;
  bool failed = false;  // the calculation threw: `failure` says what
  std::string failure;
  bool over_budget = false;  // the answer did not fit in the memory budget: dropped
  BudgetLease answer_bytes;  // the answer's bytes in the memory budget
};

// A piece of a body written as it is sent, written on the pool for the connection sending it.
struct EventLoopEngine::Piece {
  int fd = -1;
  std::uint64_t connection_id = 0;
  std::string text;
  bool more = false;             // the source has more to write
  std::size_t source_bytes = 0;  // what the source holds now
  bool failed = false;           // the source threw: the body is cut short
};

class EventLoopEngine::Loop {
 public:
  explicit Loop(EventLoopEngine& engine) : engine_(engine) {
    epoll_fd_.reset(::epoll_create1(EPOLL_CLOEXEC));
    wake_fd_.reset(::eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK));
    if (!epoll_fd_.valid() || !wake_fd_.valid()) {
      throw std::system_error(errno, std::generic_category(), "event loop");
    }
    epoll_event event{};
    event.events = EPOLLIN;
    event.data.fd = wake_fd_.get();
    if (::epoll_ctl(epoll_fd_.get(), EPOLL_CTL_ADD, wake_fd_.get(), &event) != 0) {
      throw std::system_error(errno, std::generic_category(), "event loop wake-up");
    }
    thread_ = std::thread([this] { run(); });
  }
  Loop(const Loop&) = delete;
  Loop& operator=(const Loop&) = delete;
  ~Loop() { stop(); }

  // Closes every connection and ends the thread; what the pool posts afterwards is dropped.
  void stop() {
    {
      const std::lock_guard lock(inbox_mutex_);
      quit_ = true;
    }
    wake();
    if (thread_.joinable()) thread_.join();
  }

  // From any thread: the loop takes the connection over.
  void post(std::unique_ptr<Connection> connection) {
    bool was_empty = false;
    {
      const std::lock_guard lock(inbox_mutex_);
      if (quit_) return;  // destroyed here: closed
      was_empty = inbox_.empty() && completions_.empty() && pieces_.empty();
      inbox_.push_back(std::move(connection));
    }
    if (was_empty) wake();  // otherwise a wake-up is already pending
  }

  // From a pool thread: the response of a deferred request.
  void complete(Completion completion) {
    bool was_empty = false;
    {
      const std::lock_guard lock(inbox_mutex_);
      if (quit_) return;
      was_empty = inbox_.empty() && completions_.empty() && pieces_.empty();
      completions_.push_back(std::move(completion));
    }
    if (was_empty) wake();
  }

  // From a pool thread: a piece of a body written as it is sent.
  void complete(Piece piece) {
    bool was_empty = false;
    {
      const std::lock_guard lock(inbox_mutex_);
      if (quit_) return;
      was_empty = inbox_.empty() && completions_.empty() && pieces_.empty();
      pieces_.push_back(std::move(piece));
    }
    if (was_empty) wake();
  }

 private:
  void wake() {
    const std::uint64_t one = 1;
    [[maybe_unused]] const auto n = ::write(wake_fd_.get(), &one, sizeof(one));
  }

  void run() {
    std::array<epoll_event, 256> events{};
    auto next_sweep = Clock::now() + kSweepInterval;
    for (;;) {
      const auto wait = std::chrono::duration_cast<milliseconds>(next_sweep - Clock::now());
      const int n =
          ::epoll_wait(epoll_fd_.get(), events.data(), static_cast<int>(events.size()),
                       static_cast<int>(std::clamp<milliseconds::rep>(wait.count(), 0, 1000)));
      bool woken = false;
      for (int i = 0; i < std::max(n, 0); ++i) {
        const epoll_event& event = events[static_cast<std::size_t>(i)];
        if (event.data.fd == wake_fd_.get()) {
          woken = true;
          continue;
        }
        const int fd = event.data.fd;
        const auto it = table_.find(fd);
        if (it == table_.end()) continue;  // closed earlier in this batch
        try {
          on_event(*it->second, event.events);
        } catch (...) {  // e.g. bad_alloc: lose this connection, not the loop
          close(fd);
        }
      }
      if (woken && !take_inbox()) return close_all();
      const auto now = Clock::now();
      if (now >= next_sweep || (engine_.phase_() == ServerPhase::stopped && !table_.empty())) {
        sweep(now);
        next_sweep = now + kSweepInterval;
      }
    }
  }

  // False when the loop is to quit.
  bool take_inbox() {
    std::uint64_t count = 0;
    [[maybe_unused]] const auto n = ::read(wake_fd_.get(), &count, sizeof(count));
    std::vector<std::unique_ptr<Connection>> arrived;
    std::vector<Completion> completed;
    std::vector<Piece> pieces;
    {
      const std::lock_guard lock(inbox_mutex_);
      if (quit_) return false;
      arrived.swap(inbox_);
      completed.swap(completions_);
      pieces.swap(pieces_);
    }
    for (Piece& piece : pieces) {
      const auto it = table_.find(piece.fd);
      if (it == table_.end() || it->second->id != piece.connection_id) continue;  // closed
      try {
        take_piece(*it->second, piece);
      } catch (...) {
        close(piece.fd);
      }
    }
    for (Completion& done : completed) {
      const auto it = table_.find(done.fd);
      // Closed meanwhile, or answered 503 at the calculation timeout.
      if (it == table_.end() || it->second->id != done.connection_id || !it->second->awaited) {
        continue;
      }
      Connection& connection = *it->second;
      try {
        if (done.over_budget) {
          engine_.counters_.memory_refused.fetch_add(1, std::memory_order_relaxed);
        }
        connection.charge.adopt(done.answer_bytes.release());
        answer_awaited(connection,
                       done.failed        ? DeferredOutcome::failed
                       : done.over_budget ? DeferredOutcome::over_budget
                                          : DeferredOutcome::computed,
                       std::move(done.response), done.failure);
        advance(connection);
      } catch (...) {
        close(done.fd);
      }
    }
    for (auto& owned : arrived) {
      const int fd = owned->fd.get();
      Connection& connection = *owned;
      table_.emplace(fd, std::move(owned));
      connection.idle_since = Clock::now();
      wait(connection, Wait::idle,
           connection.idle_since + engine_.settings_.limits.keep_alive_timeout, EPOLL_CTL_ADD);
    }
    return true;
  }

  void close_all() {
    while (!table_.empty()) close(table_.begin()->first);
    const std::lock_guard lock(inbox_mutex_);
    inbox_.clear();
    completions_.clear();
    pieces_.clear();
  }

  // Sets the epoll interest; false when epoll refused (the caller closes the connection).
  bool watch(Connection& connection, std::uint32_t events, int operation = EPOLL_CTL_MOD) {
    if (operation == EPOLL_CTL_MOD && connection.events == events) return true;
    epoll_event event{};
    event.events = events;
    event.data.fd = connection.fd.get();
    if (::epoll_ctl(epoll_fd_.get(), operation, connection.fd.get(), &event) != 0) {
      engine_.counters_.epoll_failures.fetch_add(1, std::memory_order_relaxed);
      return false;
    }
    connection.events = events;
    return true;
  }

  // Enters `state` until `deadline`, with the epoll interest it needs; closes the connection when
  // epoll refuses (nothing of it may be touched after a wait then).
  void wait(Connection& connection, Wait state, Clock::time_point deadline,
            int operation = EPOLL_CTL_MOD) {
    connection.waiting = state;
    connection.deadline = deadline;
    if (!watch(connection, interest(state), operation)) close(connection.fd.get());
  }

  // The only way a connection ends: out of epoll, out of the table, destroyed (fd closed).
  void close(int fd) {
    const auto it = table_.find(fd);
    if (it == table_.end()) return;
    if (it->second->awaited) abandon(*it->second);
    // Out of epoll before the descriptor can be closed and its number reused. (It fails only if
    // the descriptor is not registered, which the table rules out; counted, never ignored.)
    if (it->second->events != 0 && ::epoll_ctl(epoll_fd_.get(), EPOLL_CTL_DEL, fd, nullptr) != 0) {
      engine_.counters_.epoll_failures.fetch_add(1, std::memory_order_relaxed);
    }
    std::unique_ptr<Connection> owned = std::move(it->second);
    table_.erase(it);
    owned.reset();
  }

  enum class Read { data, again, eof, error };

  // Reads what the socket has, up to the framing's buffer limit.
  Read read_input(Connection& connection) {
    const std::size_t limit = connection.buffer_limit > 0
                                  ? connection.buffer_limit
                                  : engine_.settings_.limits.max_buffered_bytes();
    if (connection.input_begin > 0) {  // compact: keep only unread bytes
      std::memmove(connection.input.data(), connection.input.data() + connection.input_begin,
                   connection.input_end - connection.input_begin);
      connection.input_end -= connection.input_begin;
      connection.input_begin = 0;
    }
    bool got = false;
    for (;;) {
      const std::size_t unread = connection.input_end;
      if (unread >= limit) return Read::data;  // framing rejects before this; never spin
      const std::size_t wanted = std::min(unread + kReadChunk, limit);
      if (connection.input.size() < wanted) connection.input.resize(wanted);
      const std::size_t room = connection.input.size() - unread;
      const ssize_t n =
          ::recv(connection.fd.get(), connection.input.data() + unread, room, MSG_DONTWAIT);
      if (n > 0) {
        got = true;
        connection.input_end += static_cast<std::size_t>(n);
        if (static_cast<std::size_t>(n) < room) return Read::data;
        continue;  // there may be more
      }
      if (n == 0) return Read::eof;
      if (errno == EINTR) continue;
      if (errno == EAGAIN || errno == EWOULDBLOCK) return got ? Read::data : Read::again;
      return Read::error;
    }
  }

  void on_event(Connection& connection, std::uint32_t events) {
    const int fd = connection.fd.get();
    switch (connection.waiting) {
      case Wait::linger:
        if (drop_input(connection)) close(fd);
        return;
      case Wait::calculation:
        // Only the client's going is news: a failed socket, or the end of its input (as nginx
        // takes it: TCP cannot tell a half-close from a close before a write).
        if ((events & (EPOLLHUP | EPOLLERR | EPOLLRDHUP)) != 0) close(fd);
        return;
      case Wait::piece:
        // A body that has begun is finished unless the socket fails: a client that half-closed
        // after its request (`nc -N`) still reads, and one that has gone makes the next write
        // fail. Its input waits, its end included, until the body is out.
        if ((events & (EPOLLHUP | EPOLLERR)) != 0) close(fd);
        return;
      case Wait::output:
        break;  // the socket takes more (or has failed: the write says so)
      case Wait::idle:
      case Wait::request:
        if ((events & (EPOLLIN | EPOLLHUP | EPOLLERR)) != 0 && !connection.peer_eof) {
          switch (read_input(connection)) {
            case Read::data:
            case Read::again:
              break;
            case Read::eof:
              connection.peer_eof = true;
              break;
            case Read::error:
              return close(fd);
          }
        }
        break;
    }
    advance(connection);
  }

  // Serves what is buffered, sends what the socket takes, sets what to wait for next, and counts
  // what the connection then holds in the memory budget.
  void advance(Connection& connection) {
    const int fd = connection.fd.get();
    step(connection);
    const auto it = table_.find(fd);
    if (it == table_.end() || it->second.get() != &connection) return;  // closed
    if (!connection.awaited && !connection.large_body.held()) connection.body_charge = 0;
    connection.charge.set(connection.body_charge + connection.pending_output() +
                          (connection.streamed ? connection.streamed->held_bytes : 0));
  }

  // Serves and sends what it can, then waits for what comes next.
  void step(Connection& connection) {
    const int fd = connection.fd.get();
    const HttpLimits& limits = engine_.settings_.limits;
    for (;;) {
      const bool more = serve_buffered(connection);
      switch (flush(connection)) {
        case Flush::error:
          return close(fd);
        case Flush::again:
          connection.socket_queued = socket_queue(fd);
          return wait(connection, Wait::output, Clock::now() + limits.write_timeout);
        case Flush::done:
          break;
      }
      if (connection.streamed) {
        switch (produce(connection)) {
          case Produced::queued:
            return wait(connection, Wait::piece, Clock::now() + limits.calculation_timeout);
          case Produced::here:
            continue;  // send it
          case Produced::closed:
            return;
        }
      }
      if (!more) break;  // else serving stopped at the high-water mark: serve on
    }
    // No reading while a calculation runs: pipelined requests wait their turn, and an EOF or a
    // full buffer cannot wake the loop over and over.
    if (connection.awaited)
      return wait(connection, Wait::calculation, connection.awaited->deadline);
    const auto now = Clock::now();
    if (connection.close_after_output) return linger(connection, now);
    if (connection.peer_eof) return close(fd);  // a partial request can never complete
    if (connection.receiving)
      return wait(connection, Wait::request, connection.receiving->deadline);
    connection.idle_since = now;
    if (connection.input.size() > kIdleBufferBytes) std::vector<char>().swap(connection.input);
    if (connection.output.capacity() > kIdleBufferBytes) std::string().swap(connection.output);
    wait(connection, Wait::idle, now + limits.keep_alive_timeout);
  }

  static void release_large_buffers(Connection& connection) {
    if (connection.input.capacity() > kIdleBufferBytes) {
      std::vector<char>().swap(connection.input);
      connection.input_begin = connection.input_end = 0;
    }
    if (connection.decoded_body.capacity() > kIdleBufferBytes) {
      std::string().swap(connection.decoded_body);
    }
  }

  // Bytes written to the socket that its peer has not taken yet (0 when unknown).
  static std::size_t socket_queue(int fd) {
    int queued = 0;
    return ::ioctl(fd, SIOCOUTQ, &queued) == 0 && queued > 0 ? static_cast<std::size_t>(queued) : 0;
  }

  // A connection past its write timeout whose client still reads, at least at
  // HttpLimits::min_download_bytes_per_s since the wait began: the wait starts again.
  static bool reading_slowly(Connection& connection, const HttpLimits& limits) {
    if (connection.waiting != Wait::output) return false;
    const std::size_t queued = socket_queue(connection.fd.get());
    const auto seconds =
        std::chrono::duration_cast<std::chrono::seconds>(limits.write_timeout).count();
    const std::size_t enough =
        limits.min_download_bytes_per_s * static_cast<std::size_t>(std::max<long long>(seconds, 1));
    if (queued + enough > connection.socket_queued) return false;
    connection.socket_queued = queued;
    return true;
  }

  // True when it stopped at the output high-water mark with input left to serve.
  bool serve_buffered(Connection& connection) {
    const EventLoopSettings& settings = engine_.settings_;
    while (!connection.close_after_output && !connection.awaited && !connection.streamed &&
           !connection.unread().empty()) {
      if (connection.pending_output() >= settings.limits.max_pending_output_bytes) return true;
      const std::string_view unread = connection.unread();
      if (!worth_framing(connection, unread)) return false;
      const RequestFrame frame =
          classify_request(unread, settings.limits, &connection.fields, &connection.decoded_body);
      if (frame.verdict == RequestFrame::Verdict::incomplete) {
        start_request(connection);
        // Before the buffer check: an admitted large body may buffer more than the default.
        if (const auto busy =
                frame.head_bytes > 0 ? admit_large_body(connection, frame, unread) : std::nullopt) {
          (*busy == HttpFault::memory_busy ? engine_.counters_.memory_refused
                                           : engine_.counters_.large_bodies_refused)
              .fetch_add(1, std::memory_order_relaxed);
          reject(connection, refusal(*busy, frame, kLargeBodyRetryAfterSeconds));
          return false;
        }
        const std::size_t cap = connection.buffer_limit > 0 ? connection.buffer_limit
                                                            : settings.limits.max_buffered_bytes();
        if (unread.size() >= cap) {  // cannot happen: framing
          reject(connection, refusal(HttpFault::request_too_large, frame));
          return false;
        }
        if (frame.expects_continue && frame.head_bytes > 0 &&
            !connection.receiving->continue_sent) {
          connection.output.append(kContinue, sizeof(kContinue) - 1);
          connection.receiving->continue_sent = true;
        }
        return false;
      }
      if (frame.verdict == RequestFrame::Verdict::reject) {
        reject(connection, refusal(frame.fault, frame));
        return false;
      }
      HttpRequest request = framed_request(unread, frame, connection.fields,
                                           connection.decoded_body, connection.path_scratch);
      request.addresses = &connection.addresses;
      request.phase = engine_.phase_();
      const bool head_only = request.method == "HEAD";
      const bool keep_alive = request.wants_keep_alive() && connection.requests_left > 1 &&
                              request.phase == ServerPhase::serving;
      const ConnectionAfter after = !keep_alive      ? ConnectionAfter::close
                                    : request.http11 ? ConnectionAfter::keep_alive
                                                     : ConnectionAfter::keep_alive_http10;
      Reply reply = engine_.serve_(request);
      // Work for the pool reads its own copy, made before the buffers move on.
      std::shared_ptr<OwnedRequest> owned;
      if (std::holds_alternative<DeferredResponse>(reply)) {
        owned = std::make_shared<OwnedRequest>(request);
      }
      // The request's views die here: the reply owns what it needs.
      connection.consume(frame.wire_bytes);
      end_large_body(connection);
      connection.receiving.reset();
      if (connection.requests_left > 1) --connection.requests_left;
      engine_.counters_.requests.fetch_add(1, std::memory_order_relaxed);
      if (auto* deferred = std::get_if<DeferredResponse>(&reply)) {
        // The job owns a copy: a large body's buffers go now, not when the answer is sent.
        if (connection.unread().empty()) release_large_buffers(connection);
        // Answers waiting for their clients and other requests' bodies have spent the budget: no
        // more work until they drain. This request's own body is what the work is for.
        const bool over_budget = engine_.budget_.spent_besides(connection.body_charge);
        if (over_budget) engine_.counters_.memory_refused.fetch_add(1, std::memory_order_relaxed);
        if (!over_budget &&
            defer(connection, *deferred, std::move(owned), head_only, after, request.http11)) {
          return false;
        }
        respond(
            connection,
            deferred->settle(
                over_budget ? DeferredOutcome::over_budget : DeferredOutcome::pool_full, {}, {}),
            head_only, after, request.http11);
      } else {
        respond(connection, std::move(std::get<HttpResponse>(reply)), head_only, after,
                request.http11);
      }
    }
    return false;
  }

  // Writes a response's head (and its body, unless written as it is sent) to the output.
  void respond(Connection& connection, HttpResponse response, bool head_only, ConnectionAfter after,
               bool http11) {
    const bool streams = response.body_source && !head_only;
    if (streams && !http11) after = ConnectionAfter::close;  // HTTP/1.0: the close ends the body
    write_response(response, head_only, after, connection.output, http11);
    if (streams) {
      const std::size_t held = response.body_source->held_bytes();
      connection.streamed = StreamedBody{std::move(response.body_source), http11, held};
    }
    if (after == ConnectionAfter::close) connection.close_after_output = true;
  }

  enum class Produced { queued, here, closed };

  // The next piece of the body being sent, asked for once the last one has gone to the socket:
  // on the pool, or here when its queue is full (one piece is bounded; the body must go on).
  Produced produce(Connection& connection) {
    const int fd = connection.fd.get();
    const std::uint64_t id = connection.id;
    const auto write_piece = [fd, id](domain::TextSource& source) {
      Piece piece{fd, id, {}, false, 0, false};
      try {
        piece.more = source.write_next(piece.text, kBodyPieceBytes);
        piece.source_bytes = source.held_bytes();
      } catch (...) {
        piece.failed = true;
      }
      return piece;
    };
    const std::shared_ptr<domain::TextSource>& source = connection.streamed->source;
    if (engine_.pool_->try_submit(
            [this, write_piece, source] { complete(write_piece(*source)); })) {
      return Produced::queued;
    }
    Piece piece = write_piece(*source);
    return take_piece(connection, piece, false) ? Produced::here : Produced::closed;
  }

  // A piece arrived: framed into the output, the body ended after the last. A source that threw
  // cuts the body short: the connection closes (the client sees a chunked body without its end).
  // False when the connection closed. `advance`: send it now (a piece that came from the pool).
  bool take_piece(Connection& connection, Piece& piece, bool advance_now = true) {
    if (piece.failed) {
      engine_.counters_.streams_broken.fetch_add(1, std::memory_order_relaxed);
      close(connection.fd.get());
      return false;
    }
    StreamedBody& body = *connection.streamed;
    append_body_piece(piece.text, body.chunked, connection.output);
    body.held_bytes = piece.source_bytes;
    if (!piece.more) {
      end_body(body.chunked, connection.output);
      connection.streamed.reset();
    }
    if (advance_now) advance(connection);
    return true;
  }

  // Hands a deferred request to the pool (its `run` moves into the job); false when the queue is
  // full. Whatever the job does, its connection is answered: by the job's completion (a throw
  // included), else by the calculation timeout (a job that never ends, a completion lost to a
  // failed allocation). A stopped job's completion is not sent: its request is settled already.
  bool defer(Connection& connection, DeferredResponse& work, std::shared_ptr<OwnedRequest> request,
             bool head_only, ConnectionAfter after, bool http11) {
    const int fd = connection.fd.get();
    const std::uint64_t id = connection.id;
    // The answer takes the place of the body's charge, which goes once it is answered.
    const std::uint64_t body_bytes = connection.body_charge;
    auto stop = std::make_shared<std::atomic<bool>>(false);
    const bool queued = engine_.pool_->try_submit(
        [this, fd, id, stop, body_bytes, request = std::move(request), run = std::move(work.run)] {
          Completion done{fd, id, {}, false, {}, false, {}};
          try {
            done.response = run(*request, *stop);
            // Computed, the answer is held: it is kept only if the budget can count what it holds
            // beyond its body's charge.
            const std::uint64_t bytes =
                done.response.body.size() +
                (done.response.body_source ? done.response.body_source->held_bytes() : 0);
            const std::uint64_t extra = bytes - std::min(bytes, body_bytes);
            if (engine_.budget_.try_take(extra)) {
              done.answer_bytes = BudgetLease(engine_.budget_, extra);
            } else {
              done.over_budget = true;
              done.response = {};
            }
          } catch (const std::exception& error) {
            done.failed = true;
            done.failure = error.what();
          } catch (...) {  // domain::Interrupted once stopped; anything else is a bug
            done.failed = true;
            done.failure = "an exception that is not a std::exception";
          }
          if (stop->load()) return;
          complete(std::move(done));
        });
    if (!queued) return false;
    connection.awaited =
        AwaitedCalculation{std::move(work.settle),
                           std::move(stop),
                           Clock::now() + engine_.settings_.limits.calculation_timeout,
                           head_only,
                           http11,
                           after};
    return true;
  }

  // Ends the connection's wait for the pool: the response that settles its request goes out.
  void answer_awaited(Connection& connection, DeferredOutcome outcome, HttpResponse computed,
                      std::string_view failure) {
    AwaitedCalculation awaited = std::move(*connection.awaited);
    connection.awaited.reset();
    // A timed-out calculation may still hold a pool thread until its next check: the client is
    // told to come back later, on a new connection.
    if (engine_.phase_() != ServerPhase::serving || outcome == DeferredOutcome::timed_out) {
      awaited.after = ConnectionAfter::close;
    }
    respond(connection, awaited.settle(outcome, std::move(computed), failure), awaited.head_only,
            awaited.after, awaited.http11);
  }

  // The calculation timeout passed: its job is stopped and the client answered 503.
  void time_out_calculation(Connection& connection) {
    engine_.counters_.calculation_timeouts.fetch_add(1, std::memory_order_relaxed);
    connection.awaited->stop->store(true);
    answer_awaited(connection, DeferredOutcome::timed_out, {}, {});
    advance(connection);
  }

  // The connection closes while its request is on the pool (the client went away, or the server
  // stops): the job is stopped and the request settled without an answer.
  void abandon(Connection& connection) noexcept {
    engine_.counters_.calculations_abandoned.fetch_add(1, std::memory_order_relaxed);
    const AwaitedCalculation awaited = std::move(*connection.awaited);
    connection.awaited.reset();
    awaited.stop->store(true);
    try {
      awaited.settle(DeferredOutcome::abandoned, {}, {});
    } catch (...) {  // its metrics and log line are lost; nothing else can be
    }
  }

  // False while a large body is still arriving and framing it again would find it incomplete.
  static bool worth_framing(const Connection& connection, std::string_view unread) {
    if (connection.frame_again_at == 0 || unread.size() >= connection.frame_again_at) return true;
    // A chunked body may end anywhere: its last chunk and trailer end with an empty line.
    return unread.ends_with("\r\n\r\n");
  }

  // The engine's answer to `frame`, refused for `fault`.
  static EngineError refusal(HttpFault fault, const RequestFrame& frame, int retry_after_s = 0) {
    return {fault, frame.method, frame.target, frame.origin, frame.accept_language, retry_after_s};
  }

  // A request whose route takes large bodies, with a body above the default limit (or chunked):
  // takes one of the engine's places for such bodies and its length (a chunked body: the limit)
  // in the memory budget, raises what the connection may buffer and gives the transfer time at
  // HttpLimits::min_upload_bytes_per_s. Says what refused it, if anything did (uploads_busy or
  // memory_busy).
  std::optional<HttpFault> admit_large_body(Connection& connection, const RequestFrame& frame,
                                            std::string_view unread) {
    const HttpLimits& limits = engine_.settings_.limits;
    const std::size_t body_limit = limits.body_limit_for(frame.target);
    if (body_limit <= limits.max_body_bytes) return std::nullopt;
    if (!frame.chunked && frame.body_bytes <= limits.max_body_bytes) return std::nullopt;
    if (!connection.large_body.held()) {
      const std::size_t expected = frame.chunked ? body_limit : frame.body_bytes;
      const std::size_t charged = expected * kLargeBodyHeldTimes;
      if (!connection.charge.try_add(charged)) return HttpFault::memory_busy;
      if (!connection.large_body.acquire(engine_.counters_.large_bodies_receiving,
                                         limits.max_large_bodies)) {
        connection.charge.set(connection.charge.bytes() - charged);
        return HttpFault::uploads_busy;
      }
      connection.body_charge = charged;
      connection.buffer_limit = limits.max_buffered_bytes(body_limit);
      const auto transfer = std::chrono::milliseconds(
          expected * 1000 / std::max<std::size_t>(limits.min_upload_bytes_per_s, 1));
      if (connection.receiving->deadline != Clock::time_point::max()) {
        connection.receiving->deadline += transfer;
      }
    }
    connection.frame_again_at = frame.chunked
                                    ? std::max(unread.size() * 2, limits.max_buffered_bytes())
                                    : frame.body_offset + frame.body_bytes;
    return std::nullopt;
  }

  static void end_large_body(Connection& connection) {
    connection.large_body.release();
    connection.buffer_limit = 0;
    connection.frame_again_at = 0;
  }

  void start_request(Connection& connection) {
    if (connection.receiving) return;
    const auto timeout = engine_.settings_.limits.request_timeout;
    connection.receiving =
        Receiving{timeout.count() > 0 ? Clock::now() + timeout : Clock::time_point::max()};
  }

  // An error answered by the engine; nothing after it on this connection is read as a request.
  void reject(Connection& connection, const EngineError& error) {
    engine_.counters_.rejected_requests.fetch_add(1, std::memory_order_relaxed);
    connection.output += engine_.render_error_(error);
    connection.close_after_output = true;
    connection.receiving.reset();
    connection.drop_input();
    end_large_body(connection);
  }

  enum class Flush { done, again, error };

  Flush flush(Connection& connection) {
    while (connection.has_output()) {
      const ssize_t n =
          ::send(connection.fd.get(), connection.output.data() + connection.output_offset,
                 connection.pending_output(), MSG_NOSIGNAL | MSG_DONTWAIT);
      if (n < 0) {
        if (errno == EINTR) continue;
        return errno == EAGAIN || errno == EWOULDBLOCK ? Flush::again : Flush::error;
      }
      connection.output_offset += static_cast<std::size_t>(n);
    }
    connection.output.clear();
    connection.output_offset = 0;
    return Flush::done;
  }

  // The last response is out: no more writing; read and drop what the client still sends, until
  // it closes or the linger time passes.
  void linger(Connection& connection, Clock::time_point now) {
    const int fd = connection.fd.get();
    if (connection.peer_eof || engine_.phase_() == ServerPhase::stopped) return close(fd);
    ::shutdown(fd, SHUT_WR);
    connection.receiving.reset();
    wait(connection, Wait::linger, now + engine_.settings_.limits.linger_time);
  }

  // True when the connection is done (EOF or error).
  bool drop_input(Connection& connection) {
    std::array<char, 4096> sink{};
    for (;;) {
      const ssize_t n = ::recv(connection.fd.get(), sink.data(), sink.size(), MSG_DONTWAIT);
      if (n > 0) continue;
      if (n < 0 && errno == EINTR) continue;
      return !(n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK));
    }
  }

  void sweep(Clock::time_point now) {
    const bool stopped = engine_.phase_() == ServerPhase::stopped;
    const auto grace = engine_.settings_.limits.drain_idle_grace;
    std::vector<int> expired;
    std::vector<int> calculations_late;
    std::vector<int> idle_at_stop;
    std::uint64_t held = 0;
    std::uint64_t released = 0;
    for (const auto& [fd, connection] : table_) {
      const bool idle = connection->waiting == Wait::idle && connection->unread().empty();
      if (idle && now - connection->idle_since >= kSweepInterval) {
        released += connection->held_bytes();
        connection->release_buffers();
      }
      held += connection->held_bytes();
      if (now >= connection->deadline) {
        switch (connection->waiting) {
          case Wait::calculation:
            calculations_late.push_back(fd);
            break;
          case Wait::output:
            if (reading_slowly(*connection, engine_.settings_.limits)) {
              connection->deadline = now + engine_.settings_.limits.write_timeout;
            } else {
              expired.push_back(fd);
            }
            break;
          case Wait::request:
            engine_.counters_.request_timeouts.fetch_add(1, std::memory_order_relaxed);
            expired.push_back(fd);
            break;
          case Wait::idle:
          case Wait::piece:
          case Wait::linger:
            expired.push_back(fd);
            break;
        }
      } else if (stopped && (connection->waiting == Wait::linger ||
                             (idle && now - connection->idle_since >= grace))) {
        idle_at_stop.push_back(fd);
      }
    }
    engine_.counters_.buffer_bytes.fetch_add(held - reported_buffer_bytes_,
                                             std::memory_order_relaxed);
    reported_buffer_bytes_ = held;
    // Hand what thousands of connections gave back to the system too (glibc keeps freed heap
    // otherwise, and the process's memory is what a container limit counts).
    if (released >= kTrimAfterReleasedBytes) ::malloc_trim(0);
    for (const int fd : expired) close(fd);
    for (const int fd : calculations_late) {
      try {
        time_out_calculation(*table_.at(fd));
      } catch (...) {
        close(fd);
      }
    }
    // Once the listener is closed, idle connections close after the drain grace (one that brings a
    // request meanwhile is answered with Connection: close) and lingering ones at once; a request
    // in flight keeps its connection until it is answered or its deadline passes. A connection
    // whose first bytes are in the socket but not yet read is in flight too.
    for (const int fd : idle_at_stop) {
      const auto it = table_.find(fd);
      if (it == table_.end()) continue;
      char byte = 0;
      if (it->second->waiting != Wait::linger &&
          ::recv(fd, &byte, 1, MSG_PEEK | MSG_DONTWAIT) == 1) {
        on_event(*it->second, EPOLLIN);
      } else {
        close(fd);
      }
    }
  }

  EventLoopEngine& engine_;
  UniqueFd epoll_fd_;
  UniqueFd wake_fd_;
  std::mutex inbox_mutex_;
  std::vector<std::unique_ptr<Connection>> inbox_;              // guarded by inbox_mutex_
  std::vector<Completion> completions_;                         // guarded by inbox_mutex_
  std::vector<Piece> pieces_;                                   // guarded by inbox_mutex_
  bool quit_ = false;                                           // guarded by inbox_mutex_
  std::unordered_map<int, std::unique_ptr<Connection>> table_;  // loop thread only
  std::uint64_t reported_buffer_bytes_ = 0;  // this loop's share of counters_.buffer_bytes
  std::thread thread_;
};

EventLoopEngine::EventLoopEngine(EventLoopSettings settings, Serve serve, RenderError render_error,
                                 PhaseOf phase, ConnectionCounters& counters)
    : settings_(std::move(settings)),
      serve_(std::move(serve)),
      render_error_(std::move(render_error)),
      phase_(std::move(phase)),
      counters_(counters),
      budget_(settings_.memory_budget_bytes) {
  const std::size_t loops = std::max<std::size_t>(settings_.loops, 1);
  for (std::size_t i = 0; i < loops; ++i) loops_.push_back(std::make_unique<Loop>(*this));
  pool_ = std::make_unique<WorkPool>(settings_.pool, counters_.calculations);
}

// The loops' threads first, so that none hands the pool more work (a calculation, the next piece
// of a program being sent) while it goes; then the pool, whose last jobs post to loops that still
// exist and drop what they post; then the loops.
EventLoopEngine::~EventLoopEngine() {
  for (const auto& loop : loops_) loop->stop();
  pool_.reset();
  loops_.clear();
}

bool EventLoopEngine::drain(std::chrono::milliseconds limit) const {
  const auto until = Clock::now() + limit;
  while (open_connections_.load() > 0) {
    if (Clock::now() >= until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return true;
}

void EventLoopEngine::adopt(int sock) {
  UniqueFd fd(sock);
  counters_.connections.fetch_add(1, std::memory_order_relaxed);
  if (open_connections_.load() >= settings_.max_connections) {
    // At the cap: refuse at once rather than hold another descriptor. Whatever request the client
    // has sent is read first (if it is already here), so the close is less likely to reset it.
    counters_.rejected_at_cap.fetch_add(1, std::memory_order_relaxed);
    std::array<char, 4096> sink{};
    while (::recv(fd.get(), sink.data(), sink.size(), MSG_DONTWAIT) > 0) {
    }
    EngineError at_cap;  // nothing of the request was read
    at_cap.fault = HttpFault::connection_limit;
    const std::string response = render_error_(at_cap);
    [[maybe_unused]] const auto n =
        ::send(fd.get(), response.data(), response.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
    ::shutdown(fd.get(), SHUT_WR);
    return;
  }
  if (settings_.tcp_nodelay) {
    // Fails harmlessly on a socket that is not TCP (the fuzzer's socketpair).
    const int on = 1;
    ::setsockopt(fd.get(), IPPROTO_TCP, TCP_NODELAY, &on, sizeof(on));
  }
  std::unique_ptr<Connection> connection;
  try {
    connection = std::make_unique<Connection>(
        std::move(fd), next_connection_id_.fetch_add(1, std::memory_order_relaxed),
        std::max<std::size_t>(settings_.keep_alive_max_requests, 1), open_connections_, budget_);
  } catch (...) {
    return;  // out of memory: the descriptor closes with `fd`
  }
  const std::size_t loop = next_loop_.fetch_add(1, std::memory_order_relaxed) % loops_.size();
  loops_[loop]->post(std::move(connection));
}

}  // namespace cutcalc::service
