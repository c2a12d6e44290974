#include "support/exchange_log.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace cutcalc::testing {
namespace {

std::string log_path() {
  if (const char* path = std::getenv("CUTCALC_EXCHANGE_LOG"); path != nullptr && *path != '\0') {
    return path;
  }
  return CUTCALC_EXCHANGE_LOG;
}

std::string current_test() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return info == nullptr ? std::string("(no test)")
                         : std::string(info->test_suite_name()) + "." + info->name();
}

nlohmann::json header_object(const httplib::Headers& headers) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [name, value] : headers) {
    out[name] = value;  // a repeated name keeps its last value
  }
  return out;
}

void record(const httplib::Request& request, const httplib::Response& response) {
  constexpr std::size_t kRequestBodyKept = 4096;  // enough to tell which request it was
  const nlohmann::json entry = {{"test", current_test()},
                                {"method", request.method},
                                {"path", request.path},
                                {"request_headers", header_object(request.headers)},
                                {"request_body", request.body.substr(0, kRequestBodyKept)},
                                {"status", response.status},
                                {"response_headers", header_object(response.headers)},
                                {"body", response.body}};
  const std::string line =
      entry.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
  const std::string path = log_path();
  const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) {
    ADD_FAILURE() << "cannot open the exchange log " << path;
    return;
  }
  ::flock(fd, LOCK_EX);  // parallel test processes: one whole line each
  for (std::size_t written = 0; written < line.size();) {
    const ssize_t n = ::write(fd, line.data() + written, line.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      ADD_FAILURE() << "cannot write the exchange log " << path;
      break;
    }
    written += static_cast<std::size_t>(n);
  }
  ::close(fd);  // releases the lock
}

}  // namespace

void log_exchanges(httplib::Client& client) { client.set_logger(record); }

}  // namespace cutcalc::testing
