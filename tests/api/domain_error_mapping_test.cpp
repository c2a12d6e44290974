// A domain error becomes one problem: the API code of the same name (one list), the pointer the
// endpoint gives for its code (plus the element's index), the error's limit as `maximum`, and
// not_converged a 500 without errors.

#include "api/domain_error_mapping.h"

#include <gtest/gtest.h>

#include <string>

namespace cutcalc::api {
namespace {

using domain::make_error;

TEST(DomainErrorMapping, EveryDomainCodeBecomesTheApiCodeOfTheSameName) {
  for (int i = 0; i < static_cast<int>(domain::ErrorCode::not_converged); ++i) {
    const auto code = static_cast<domain::ErrorCode>(i);
    const Problem problem = to_problem(make_error(code), {});
    EXPECT_EQ(problem.kind, ProblemKind::impossible_input) << i;
    ASSERT_EQ(problem.errors.size(), 1U) << i;
    EXPECT_EQ(code_name(problem.errors[0].code), domain::error_code_name(code));
    EXPECT_TRUE(in_errors_list(problem.errors[0].code)) << domain::error_code_name(code);
    EXPECT_EQ(problem.errors[0].pointer, "") << domain::error_code_name(code);
    EXPECT_EQ(problem.errors[0].params, nlohmann::json::object());
  }
}

TEST(DomainErrorMapping, TheEndpointsPointerAndTheElementsIndexLocateTheError) {
  constexpr ErrorPointer kPointers[] = {
      {domain::ErrorCode::no_contact, "/elsewhere"},
      {domain::ErrorCode::contact_angle_outside_arc, "/contact_angles_deg"},
  };
  domain::DomainError error = make_error(domain::ErrorCode::contact_angle_outside_arc);
  error.index = 3;
  EXPECT_EQ(to_problem(error, kPointers).errors.at(0).pointer, "/contact_angles_deg/3");
  EXPECT_EQ(to_problem(make_error(domain::ErrorCode::bore_feed_too_large), kPointers)
                .errors.at(0)
                .pointer,
            "");
}

TEST(DomainErrorMapping, TheErrorsLimitIsItsMaximum) {
  const Problem problem =
      to_problem(domain::make_limit_error(domain::ErrorCode::pass_program_too_large, 200000), {});
  ASSERT_EQ(problem.errors.size(), 1U);
  EXPECT_EQ(problem.errors[0].code, ErrorCode::pass_program_too_large);
  EXPECT_EQ(problem.errors[0].params, (nlohmann::json{{"maximum", 200000.0}}));
  EXPECT_EQ(render_message(problem.errors[0].code, problem.errors[0].params, Language::en),
            "the program would have more than 200000 blocks");
}

TEST(DomainErrorMapping, NotConvergedIsAnInternalErrorWithoutFieldErrors) {
  const Problem problem = to_problem(make_error(domain::ErrorCode::not_converged, "a bug"), {});
  EXPECT_EQ(problem.kind, ProblemKind::internal_error);
  EXPECT_TRUE(problem.errors.empty());
  ASSERT_TRUE(problem.detail.has_value());
  EXPECT_EQ(problem.detail->code, ErrorCode::internal_error);
}

}  // namespace
}  // namespace cutcalc::api
