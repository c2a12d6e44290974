#pragma once
// The outcome of a domain calculation: a value or a DomainError, never both. Domain code reports
// impossible inputs through ErrorCode (mapped once to HTTP in api/), never by exceptions or
// asserts.

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <variant>

namespace cutcalc::domain {

// Every way a validated request can still be impossible for the model. The API layer maps each
// code to one HTTP status and one JSON Pointer (api/errors/domain_error_mapping.cpp).
enum class ErrorCode {
  no_contact,                     // the cutter band misses the workpiece (E2: W <= 0)
  stroke_shorter_than_entry,      // L_rx < L_vr (E23)
  entry_arc_wider_than_diameter,  // entry width_mm > 2 radius_mm
  exit_arc_wider_than_diameter,   // exit width_mm > 2 radius_mm
  exit_width_mismatch,            // exit width differs from the entry / part width
  offset_with_several_passes,     // offset_mm given with N1 > 1 lateral passes (E27)
  allowance_wider_than_part,      // H1 > B
  allowance_not_full_width,       // H1 != B with N1 > 1
  width_of_cut_exceeds_diameter,  // t > D
  entry_feed_exceeds_feed,        // S_z1 > S_z
  too_many_lateral_passes,        // N1 above the service's limit (a guard, not the model; E24)
  too_many_depth_passes,          // N2 above the service's limit (a guard, not the model; E24)
  contact_angle_outside_arc,      // |rho_i| > rho_e + 1e-9 deg; DomainError::index = i
  target_needs_minor_edge_angle,  // target_rz_um with phi1 = 0: Rz = 0 for every feed (R.4)
  cutter_not_smaller_than_bore,   // r >= R (B.5)
  bore_feed_too_large,            // eps >= 1, alpha >= 180 deg, theta'(0) = 0 or no bracket (B.4)
  tolerance_unreachable,        // polygon arc fit needs more than 1000 biarcs per ellipse arc (P21)
  program_too_large,            // polygon program over 200 000 arc blocks (section 10)
  pass_program_too_large,       // pass program over 200 000 blocks (programs.md 1.2)
  program_needs_straight_path,  // pass program with extra_path_mm > 0 (programs.md 1.2)
  word_prints_as_zero,          // an F or S word that would print as 0 (programs.md 1.2)
  not_converged,                // a numerical procedure failed: a bug, reported as 500
};

struct DomainError {
  ErrorCode code;
  std::string detail;                // English, for people; no internal state
  std::optional<std::size_t> index;  // element of a list input the error is about, if any
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

inline DomainError make_error(ErrorCode code, std::string detail) {
  return DomainError{code, std::move(detail), std::nullopt};
}

}  // namespace cutcalc::domain
