#include "support/openapi_contract.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <regex>
#include <stdexcept>
#include <string_view>
#include <utility>

#include <yaml-cpp/yaml.h>

extern char** environ;

namespace cutcalc::test_support {
namespace {

using nlohmann::json;

// ------------------------------------------------------------------------------------------------
// YAML -> JSON, plain scalars typed by the YAML 1.2 core schema (what OpenAPI tools assume).

const std::regex& int_re() {
  static const std::regex re(R"([-+]?[0-9]+)");
  return re;
}
const std::regex& float_re() {
  static const std::regex re(R"([-+]?(\.[0-9]+|[0-9]+(\.[0-9]*)?)([eE][-+]?[0-9]+)?)");
  return re;
}

std::string_view strip_plus(std::string_view s) {
  return (!s.empty() && s.front() == '+') ? s.substr(1) : s;
}

json integer_scalar(std::string_view text, int base) {
  std::int64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value, base);
  if (ec == std::errc() && end == text.data() + text.size()) {
    return value;
  }
  double d = 0;  // out of range for int64: keep it as a number anyway
  std::from_chars(text.data(), text.data() + text.size(), d);
  return d;
}

json plain_scalar(const std::string& s) {
  if (s.empty() || s == "~" || s == "null" || s == "Null" || s == "NULL") {
    return nullptr;
  }
  if (s == "true" || s == "True" || s == "TRUE") {
    return true;
  }
  if (s == "false" || s == "False" || s == "FALSE") {
    return false;
  }
  if (std::regex_match(s, int_re())) {
    return integer_scalar(strip_plus(s), 10);
  }
  if (s.size() > 2 && s[0] == '0' && s[1] == 'o' &&
      s.find_first_not_of("01234567", 2) == std::string::npos) {
    return integer_scalar(std::string_view(s).substr(2), 8);
  }
  if (s.size() > 2 && s[0] == '0' && s[1] == 'x' &&
      s.find_first_not_of("0123456789abcdefABCDEF", 2) == std::string::npos) {
    return integer_scalar(std::string_view(s).substr(2), 16);
  }
  if (std::regex_match(s, float_re())) {
    const std::string_view text = strip_plus(s);
    double d = 0;
    std::from_chars(text.data(), text.data() + text.size(), d);
    return d;
  }
  if (s == ".inf" || s == ".Inf" || s == ".INF" || s == "+.inf" || s == "+.Inf" || s == "+.INF") {
    return HUGE_VAL;
  }
  if (s == "-.inf" || s == "-.Inf" || s == "-.INF") {
    return -HUGE_VAL;
  }
  if (s == ".nan" || s == ".NaN" || s == ".NAN") {
    return std::nan("");
  }
  return s;
}

json yaml_to_json(const YAML::Node& node, const std::string& where) {
  switch (node.Type()) {
    case YAML::NodeType::Null:
      return nullptr;
    case YAML::NodeType::Scalar: {
      const std::string& tag = node.Tag();
      if (tag == "!" || tag == "tag:yaml.org,2002:str") {
        return node.Scalar();  // quoted or block scalar
      }
      return plain_scalar(node.Scalar());
    }
    case YAML::NodeType::Sequence: {
      json out = json::array();
      std::size_t i = 0;
      for (const auto& item : node) {
        out.push_back(yaml_to_json(item, where + "/" + std::to_string(i++)));
      }
      return out;
    }
    case YAML::NodeType::Map: {
      json out = json::object();
      for (const auto& kv : node) {
        if (!kv.first.IsScalar()) {
          throw std::runtime_error("openapi: non-scalar mapping key at " + where);
        }
        const std::string key = kv.first.Scalar();
        if (out.contains(key)) {
          std::string message = "openapi: duplicate key '";
          message.append(key).append("' at ").append(where);
          throw std::runtime_error(message);
        }
        out[key] = yaml_to_json(kv.second, std::string(where).append("/").append(key));
      }
      return out;
    }
    case YAML::NodeType::Undefined:
      break;
  }
  throw std::runtime_error("openapi: undefined YAML node at " + where);
}

}  // namespace

// tools/contract/check.mjs serve, talked to over a socketpair: one JSON line each way.
class OpenApiContract::Checker {
 public:
  Checker(const std::string& openapi_path, Compile compile) {
    int fds[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0) {
      throw std::runtime_error("openapi: socketpair failed");
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDIN_FILENO);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
    // Nothing else: an inherited socket of a test would stay open as long as the checker lives.
    posix_spawn_file_actions_addclosefrom_np(&actions, STDERR_FILENO + 1);
    std::string node = CUTCALC_NODE;
    std::string script = CUTCALC_CONTRACT_CHECKER;
    std::string mode = "serve";
    std::string lazy = "--lazy";
    std::string document = openapi_path;
    std::vector<char*> argv = {node.data(), script.data(), mode.data()};
    if (compile == Compile::when_used) argv.push_back(lazy.data());
    argv.push_back(document.data());
    argv.push_back(nullptr);
    const int spawned = posix_spawn(&pid_, node.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[1]);
    fd_ = fds[0];
    if (spawned != 0) {
      ::close(fd_);
      throw std::runtime_error("openapi: cannot start " + node + " " + script);
    }
    const nlohmann::json ready = read_line();
    if (!ready.value("ready", false)) {
      throw std::runtime_error(ready.value("error", "openapi: the contract checker did not start"));
    }
  }
  ~Checker() {
    ::close(fd_);  // end of input: the checker exits
    int status = 0;
    ::waitpid(pid_, &status, 0);
  }
  Checker(const Checker&) = delete;
  Checker& operator=(const Checker&) = delete;

  std::vector<std::string> violations(const nlohmann::json& question) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const std::string line =
        question.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
    for (std::size_t sent = 0; sent < line.size();) {
      const ssize_t n = ::send(fd_, line.data() + sent, line.size() - sent, MSG_NOSIGNAL);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) throw std::runtime_error("openapi: the contract checker is gone");
      sent += static_cast<std::size_t>(n);
    }
    const nlohmann::json answer = read_line();
    if (!answer.contains("violations")) {
      throw std::runtime_error("openapi: " + answer.value("error", answer.dump()));
    }
    return answer.at("violations").get<std::vector<std::string>>();
  }

 private:
  nlohmann::json read_line() {
    std::size_t end;
    while ((end = buffer_.find('\n')) == std::string::npos) {
      char chunk[65536];
      const ssize_t n = ::read(fd_, chunk, sizeof chunk);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) throw std::runtime_error("openapi: the contract checker ended unexpectedly");
      buffer_.append(chunk, static_cast<std::size_t>(n));
    }
    const nlohmann::json answer = nlohmann::json::parse(buffer_.substr(0, end), nullptr, false);
    buffer_.erase(0, end + 1);
    if (!answer.is_object()) throw std::runtime_error("openapi: unreadable checker answer");
    return answer;
  }

  pid_t pid_ = -1;
  int fd_ = -1;
  std::string buffer_;
  std::mutex mutex_;
};

OpenApiContract::OpenApiContract(nlohmann::json document, std::shared_ptr<Checker> checker)
    : document_(std::move(document)), checker_(std::move(checker)) {}

OpenApiContract OpenApiContract::load(const std::string& path, Compile compile) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw std::runtime_error("openapi: cannot load " + path + ": " + e.what());
  }
  nlohmann::json doc = yaml_to_json(root, "");
  return OpenApiContract(std::move(doc), std::make_shared<Checker>(path, compile));
}

nlohmann::json OpenApiContract::document() const { return document_; }

std::vector<std::string> OpenApiContract::check_response(const std::string& method,
                                                         const std::string& path, int status,
                                                         const std::string& content_type,
                                                         const nlohmann::json& body) const {
  return checker_->violations({{"op", "response"},
                               {"method", method},
                               {"path", path},
                               {"status", status},
                               {"content_type", content_type},
                               {"body", body}});
}

std::vector<std::string> OpenApiContract::check_request(const std::string& method,
                                                        const std::string& path,
                                                        const nlohmann::json& body) const {
  return checker_->violations(
      {{"op", "request"}, {"method", method}, {"path", path}, {"body", body}});
}

std::vector<std::string> OpenApiContract::check_response_headers(
    const std::string& method, const std::string& path, int status,
    const std::map<std::string, std::string>& headers) const {
  return checker_->violations({{"op", "headers"},
                               {"method", method},
                               {"path", path},
                               {"status", status},
                               {"headers", headers}});
}

std::vector<std::string> OpenApiContract::check_schema(const std::string& schema_ref,
                                                       const nlohmann::json& value) const {
  return checker_->violations({{"op", "schema"}, {"ref", schema_ref}, {"value", value}});
}

}  // namespace cutcalc::test_support
