#pragma once
// The outcome of a domain calculation: a value or a DomainError, never both. Domain code reports
// impossible inputs through ErrorCode (mapped once to HTTP in api/domain_error_mapping.cpp), never
// by exceptions or asserts.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

namespace cutcalc::domain {

// Every way a validated request can still be impossible for the model: the one list
// (domain/common/error_codes.def), then not_converged. api/ turns each into one HTTP problem
// (api/domain_error_mapping.cpp); the endpoint says which request member it is about.
enum class ErrorCode {
#define CUTCALC_DOMAIN_ERROR(name) name,
#include "domain/common/error_codes.def"
#undef CUTCALC_DOMAIN_ERROR
  not_converged,  // a numerical procedure failed: a bug, logged and reported as 500
};

// The code's name as the list spells it ("no_contact"): the wire name of every code but
// not_converged, which never reaches a client.
constexpr std::string_view error_code_name(ErrorCode code) {
  constexpr std::string_view kNames[] = {
#define CUTCALC_DOMAIN_ERROR(name) #name,
#include "domain/common/error_codes.def"
#undef CUTCALC_DOMAIN_ERROR
      "not_converged"};
  return kNames[static_cast<std::size_t>(code)];
}

struct DomainError {
  ErrorCode code;
  // For logs and tests only, never sent to a client (the API's catalogue has the sentences): which
  // condition refused, in the model's terms, when the code alone does not say it; else empty.
  std::string detail;
  std::optional<std::size_t> index;  // element of a list input the error is about, if any
  std::optional<double> limit;       // the service's limit that was exceeded ({maximum}), if any
};

template <class T>
class Result {
 public:
  Result(T value) : state_(std::move(value)) {}            // NOLINT(google-explicit-constructor)
  Result(DomainError error) : state_(std::move(error)) {}  // NOLINT(google-explicit-constructor)

  [[nodiscard]] bool ok() const { return std::holds_alternative<T>(state_); }
  [[nodiscard]] const T& value() const { return std::get<T>(state_); }
  [[nodiscard]] T& value() { return std::get<T>(state_); }
  [[nodiscard]] const DomainError& error() const { return std::get<DomainError>(state_); }

 private:
  std::variant<T, DomainError> state_;
};

inline DomainError make_error(ErrorCode code, std::string detail = {}) {
  return DomainError{code, std::move(detail), std::nullopt, std::nullopt};
}

// A code that states the limit the input exceeded.
inline DomainError make_limit_error(ErrorCode code, double limit) {
  return DomainError{code, {}, std::nullopt, limit};
}

}  // namespace cutcalc::domain
