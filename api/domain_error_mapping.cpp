#include "api/domain_error_mapping.h"

#include <string>

#include <spdlog/spdlog.h>

namespace cutcalc::api {
namespace {

// api::ErrorCode starts with the domain's list: the same code has the same number.
ErrorCode api_code(domain::ErrorCode code) { return static_cast<ErrorCode>(code); }

constexpr bool domain_codes_lead_the_api_codes() {
#define CUTCALC_DOMAIN_ERROR(name)                                                      \
  if (static_cast<int>(domain::ErrorCode::name) != static_cast<int>(ErrorCode::name)) { \
    return false;                                                                       \
  }
#include "domain/common/error_codes.def"
#undef CUTCALC_DOMAIN_ERROR
  return true;
}
static_assert(domain_codes_lead_the_api_codes(), "api::ErrorCode must start with the domain list");

}  // namespace

Problem to_problem(const domain::DomainError& error, std::span<const ErrorPointer> pointers) {
  if (error.code == domain::ErrorCode::not_converged) {
    // Validated input that the numerics cannot answer is our bug: log the detail, answer
    // generically.
    spdlog::error("numerical procedure failed on validated input: {}", error.detail);
    return Problem{ProblemKind::internal_error, Message{ErrorCode::internal_error}, {}};
  }
  std::string pointer;
  for (const ErrorPointer& entry : pointers) {
    if (entry.code == error.code) {
      pointer = entry.pointer;
      break;
    }
  }
  if (error.index) {
    pointer += '/';
    pointer += std::to_string(*error.index);
  }
  nlohmann::json params = nlohmann::json::object();
  if (error.limit) params["maximum"] = *error.limit;
  return Problem{ProblemKind::impossible_input,
                 std::nullopt,
                 {FieldError{std::move(pointer), api_code(error.code), std::move(params)}}};
}

}  // namespace cutcalc::api
