// Property test: the implementation (vector form V7) against the cosine-law form V9-V11 written
// here independently, with the contact radius from paper eq. (1) (V4 without hypot), the engagement
// half-angle from V3 (arccos) and the sense from the sign of v_T . v_w (V6, V12), on thousands of
// random valid requests (spec resultant-speeds.md, section 4 notes).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "domain/kinematics/resultant_speeds_test_support.h"

namespace {

using cutcalc::test::kinematics::all_finite;
using cutcalc::test::kinematics::CenterDistance;
using cutcalc::test::kinematics::computed;
using cutcalc::test::kinematics::ContactPointSpeeds;
using cutcalc::test::kinematics::degrees;
using cutcalc::test::kinematics::FlatDepth;
using cutcalc::test::kinematics::MillingSense;
using cutcalc::test::kinematics::radians;
using cutcalc::test::kinematics::ResultantSpeedsParams;

constexpr double kRel = 1e-12;  // the spec's agreement bound between the two forms
// Largest cancellation factor (sum of |terms| / |result|) under which a value is compared: with
// ~10 roundings of 1.1e-16 each, 100 keeps either form's error near 1e-13, well inside kRel.
constexpr double kMaxCancellation = 100.0;
constexpr int kRequests = 4000;
constexpr int kAnglesPerRequest = 4;

struct Draw {
  ResultantSpeedsParams params;
  double a_w = 0.0;  // a_w as V1 forms it, or as given
};

// Log-uniform over [lo, hi]: radii and speeds span decades.
double log_uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::exp(std::uniform_real_distribution<double>(std::log(lo), std::log(hi))(rng));
}

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// A valid request: both placements, still and turning workpieces, both feed signs and zero,
// both senses, any lambda; deep and shallow cuts, a_w below and above R1.
Draw random_request(std::mt19937_64& rng) {
  Draw d;
  ResultantSpeedsParams& p = d.params;
  const double R1 = log_uniform(rng, 0.5, 50.0);
  const double R2 = log_uniform(rng, 0.5, 100.0);
  p.tool_radius_mm = R1;
  p.workpiece_radius_mm = R2;
  if (uniform(rng, 0.0, 1.0) < 0.5) {
    const double lo = std::abs(R2 - R1);
    const double hi = R1 + R2;
    d.a_w = uniform(rng, lo + 1e-6 * hi, hi - 1e-6 * hi);
    p.placement = CenterDistance{d.a_w};
  } else {
    const double t = uniform(rng, 1e-6, 1.0 - 1e-6) * 2.0 * std::min(R1, R2);
    d.a_w = R2 - t + R1;  // V1
    p.placement = FlatDepth{t};
  }
  p.tool_speed_rpm = log_uniform(rng, 100.0, 20000.0);
  p.workpiece_speed_rpm = uniform(rng, 0.0, 1.0) < 0.1 ? 0.0 : log_uniform(rng, 0.1, 2000.0);
  p.milling = uniform(rng, 0.0, 1.0) < 0.5 ? MillingSense::up : MillingSense::down;
  const double feed = uniform(rng, 0.0, 1.0) < 0.2 ? 0.0 : log_uniform(rng, 1.0, 1e5);
  p.tool_feed_mm_per_min = uniform(rng, 0.0, 1.0) < 0.5 ? feed : -feed;
  p.edge_inclination_deg = uniform(rng, -89.0, 89.0);
  return d;
}

// The cosine-law form at one contact angle, everything in mm/min and radians, together with the
// cancellation factor of each value (how much larger its terms are than the value itself).
struct CosineLaw {
  double R2_contact = 0.0;  // R2', paper eq. (1)
  double V_T = 0.0;
  double v_S2 = 0.0;
  double u_s = 0.0;    // V9
  double v_e = 0.0;    // V10
  double angle = 0.0;  // V11, radians
  double cond_R2 = 0.0;
  double cond_u_s = 0.0;
  double cond_v_e = 0.0;
  double cond_angle = 0.0;
  double g = 0.0;         // g(rho)
  double dot_sign = 0.0;  // sign of v_T . v_w / (omega1 R1) with s2 for omega2's sign
};

// V6 spelled out on its own: same rotation senses for up-milling on a_w > R1, for down-milling on
// a_w <= R1.
double rotation_sign(MillingSense milling, double a_w, double R1) {
  if (a_w > R1) {
    return milling == MillingSense::up ? 1.0 : -1.0;
  }
  return milling == MillingSense::down ? 1.0 : -1.0;
}

CosineLaw cosine_law(const Draw& d, double rho_deg) {
  const ResultantSpeedsParams& p = d.params;
  const double R1 = p.tool_radius_mm;
  const double a_w = d.a_w;
  const double rho = radians(rho_deg);
  const double s = std::sin(rho);
  const double c = std::cos(rho);
  const double s2 = rotation_sign(p.milling, a_w, R1);
  const double omega1 = 2.0 * std::numbers::pi * p.tool_speed_rpm;
  const double omega2 = s2 * 2.0 * std::numbers::pi * p.workpiece_speed_rpm;
  const double v_s1 = p.tool_feed_mm_per_min;

  CosineLaw r;
  // Paper eq. (1), a_w^2 + R1^2 - 2 a_w R1 cos rho, rearranged into non-negative terms so that
  // this side never cancels. The implementation's a_w - R1 cos rho does cancel when the contact
  // point is close to the workpiece axis, by about max(a_w, R1) / R2'.
  const double half_sin = std::sin(rho / 2.0);
  const double R2_sq = (a_w - R1) * (a_w - R1) + 4.0 * a_w * R1 * half_sin * half_sin;
  r.R2_contact = std::sqrt(R2_sq);
  r.cond_R2 = std::max(a_w, R1) / r.R2_contact;
  r.V_T = omega1 * R1;
  r.v_S2 = 2.0 * std::numbers::pi * r.R2_contact * p.workpiece_speed_rpm;
  r.g = R1 - a_w * c;

  const double cross_term = 2.0 * v_s1 * omega2 * R1 * s;
  const double u_s_sq = v_s1 * v_s1 + r.v_S2 * r.v_S2 + cross_term;  // V9
  r.u_s = std::sqrt(std::max(u_s_sq, 0.0));
  r.cond_u_s = (v_s1 * v_s1 + r.v_S2 * r.v_S2 + std::abs(cross_term)) / u_s_sq;

  const double projection = v_s1 * s + omega2 * r.g;                        // -(v_T . u_s) / V_T
  const double v_e_sq = r.V_T * r.V_T + u_s_sq - 2.0 * r.V_T * projection;  // V10
  r.v_e = std::sqrt(std::max(v_e_sq, 0.0));
  r.cond_v_e = (r.V_T * r.V_T + r.cond_u_s * u_s_sq +
                2.0 * r.V_T * (std::abs(v_s1 * s) + std::abs(omega2) * (R1 + a_w * std::abs(c)))) /
               v_e_sq;

  // V11: Y = v_T x v_e / V_T, X = v_T . v_e / V_T. Their term sums also cover the terms that the
  // vector form cancels (omega2 R1 sin rho cos rho appears there in both components).
  const double Y = omega2 * a_w * s + v_s1 * c;
  const double X = r.V_T - v_s1 * s - omega2 * r.g;
  r.angle = std::atan2(Y, X);
  const double w2 = std::abs(omega2);
  const double Y_terms = w2 * std::abs(s) * (a_w + 2.0 * R1 * std::abs(c)) + std::abs(v_s1 * c);
  const double X_terms =
      r.V_T + std::abs(s) * (std::abs(v_s1) + w2 * R1) + w2 * std::abs(c) * (a_w + R1) + w2 * R1;
  // d(angle) <= eps (|X| Y_terms + |Y| X_terms) / (X^2 + Y^2), relative to |angle|.
  r.cond_angle =
      (std::abs(X) * Y_terms + std::abs(Y) * X_terms) / ((X * X + Y * Y) * std::abs(r.angle));
  r.dot_sign = s2 * r.g;
  return r;
}

bool well_conditioned(double cond) { return std::isfinite(cond) && cond <= kMaxCancellation; }

struct Counts {
  int points = 0;
  int R2 = 0;
  int u_s = 0;
  int v_e = 0;
  int angle = 0;
  int sense = 0;
  int rho_e = 0;
};

std::string describe(const Draw& d, double rho_deg) {
  std::ostringstream out;
  out.precision(17);
  out << "R1=" << d.params.tool_radius_mm << " R2=" << d.params.workpiece_radius_mm
      << " a_w=" << d.a_w << " n1=" << d.params.tool_speed_rpm
      << " n2=" << d.params.workpiece_speed_rpm << " v_s1=" << d.params.tool_feed_mm_per_min
      << " milling=" << (d.params.milling == MillingSense::up ? "up" : "down")
      << " lambda=" << d.params.edge_inclination_deg << " rho=" << rho_deg;
  return out.str();
}

void compare_point(const Draw& d, const ContactPointSpeeds& got, Counts& counts) {
  const double rho_deg = got.contact_angle_deg;
  const CosineLaw want = cosine_law(d, rho_deg);
  const std::string where = describe(d, rho_deg);
  ++counts.points;
  ASSERT_TRUE(all_finite(got)) << where;

  EXPECT_NEAR(got.tool_speed_m_per_min * 1000.0, want.V_T, kRel * want.V_T) << where;
  if (well_conditioned(want.cond_R2)) {
    ++counts.R2;
    EXPECT_NEAR(got.contact_radius_mm, want.R2_contact, kRel * want.R2_contact) << where;
    EXPECT_NEAR(got.workpiece_speed_m_per_min * 1000.0, want.v_S2, kRel * want.v_S2) << where;
    EXPECT_NEAR(got.kinematic_ratio, want.v_S2 / want.V_T, kRel * want.v_S2 / want.V_T) << where;
  }
  if (well_conditioned(want.cond_u_s) && well_conditioned(want.cond_R2)) {
    ++counts.u_s;
    EXPECT_NEAR(got.resultant_feed_mm_per_min, want.u_s, kRel * want.u_s) << where;
  }
  if (well_conditioned(want.cond_v_e) && well_conditioned(want.cond_R2)) {
    ++counts.v_e;
    const double v_e = got.resultant_speed_m_per_min * 1000.0;
    EXPECT_NEAR(v_e, want.v_e, kRel * want.v_e) << where;
    // V14 on the implementation's own |v_e|.
    const double lambda = radians(d.params.edge_inclination_deg);
    EXPECT_NEAR(got.normal_speed_m_per_min, got.resultant_speed_m_per_min * std::cos(lambda),
                kRel * got.resultant_speed_m_per_min)
        << where;
    EXPECT_NEAR(got.along_edge_speed_m_per_min, got.resultant_speed_m_per_min * std::sin(lambda),
                kRel * got.resultant_speed_m_per_min)
        << where;
  }
  if (want.angle != 0.0 && well_conditioned(want.cond_angle)) {
    ++counts.angle;
    // Both sides of the cut at +-180 deg are the same direction; the spec reports +180.
    const double angle = degrees(want.angle);
    double difference = got.resultant_angle_deg - angle;
    if (std::abs(difference) > 180.0) {
      difference -= std::copysign(360.0, difference);
    }
    EXPECT_NEAR(difference, 0.0, kRel * std::abs(angle)) << where << " angle " << angle;
  }
  EXPECT_GT(got.resultant_angle_deg, -180.0) << where;
  EXPECT_LE(got.resultant_angle_deg, 180.0) << where;
  EXPECT_GT(got.contact_polar_angle_deg, -180.0) << where;
  EXPECT_LE(got.contact_polar_angle_deg, 180.0) << where;
  // V12 away from the flip point, where the sign of g is beyond rounding.
  if (std::abs(want.g) > 1e-9 * (d.params.tool_radius_mm + d.a_w)) {
    ++counts.sense;
    const MillingSense sense = want.dot_sign > 0.0 ? MillingSense::down : MillingSense::up;
    EXPECT_EQ(got.sense, sense) << where;
    // V15: no flip along the arc for a_w <= R1 or a_w^2 >= R1^2 + R2^2.
    const double R1 = d.params.tool_radius_mm;
    const double R2 = d.params.workpiece_radius_mm;
    if (d.a_w <= R1 || d.a_w * d.a_w >= R1 * R1 + R2 * R2) {
      EXPECT_EQ(got.sense, d.params.milling) << where;
    }
  }
}

// V3 by arccos, compared where neither the arccos nor its argument loses digits.
void compare_half_angle(const Draw& d, double rho_e_deg, Counts& counts) {
  const double R1 = d.params.tool_radius_mm;
  const double R2 = d.params.workpiece_radius_mm;
  const double numerator = d.a_w * d.a_w + R1 * R1 - R2 * R2;
  const double cosine = numerator / (2.0 * d.a_w * R1);
  const double cond = (d.a_w * d.a_w + R1 * R1 + R2 * R2) / std::abs(numerator);
  if (std::abs(cosine) < 0.999 && cond < 1e3) {
    ++counts.rho_e;
    const double rho_e = degrees(std::acos(cosine));
    // Spec accuracy 1e-9: the flat-depth form works from t, V3 here from the rounded a_w.
    EXPECT_NEAR(rho_e_deg, rho_e, 1e-9 * rho_e) << describe(d, 0.0);
  }
}

TEST(ResultantSpeedsProperty, VectorFormAgreesWithCosineLaw) {
  std::mt19937_64 rng(0x000C07CA1CULL);
  Counts counts;
  for (int i = 0; i < kRequests; ++i) {
    Draw d = random_request(rng);
    const auto defaults = computed(d.params);
    ASSERT_EQ(defaults.points.size(), 3u) << describe(d, 0.0);
    const double rho_e = defaults.engagement_half_angle_deg;
    compare_half_angle(d, rho_e, counts);

    std::vector<double> angles;
    for (int k = 0; k < kAnglesPerRequest; ++k) {
      angles.push_back(uniform(rng, -rho_e, rho_e));
    }
    d.params.contact_angles_deg = angles;
    const auto listed = computed(d.params);
    ASSERT_EQ(listed.points.size(), angles.size()) << describe(d, 0.0);
    EXPECT_EQ(listed.engagement_half_angle_deg, rho_e);
    for (const auto& point : defaults.points) {
      compare_point(d, point, counts);
    }
    for (const auto& point : listed.points) {
      compare_point(d, point, counts);
    }
    if (testing::Test::HasFatalFailure()) {
      return;
    }
  }
  // The comparison must actually have happened for most points, not been skipped as
  // ill-conditioned.
  const int total = kRequests * (3 + kAnglesPerRequest);
  EXPECT_EQ(counts.points, total);
  EXPECT_GE(counts.R2, total * 95 / 100);
  EXPECT_GE(counts.u_s, total * 90 / 100);
  EXPECT_GE(counts.v_e, total * 90 / 100);
  EXPECT_GE(counts.angle, total * 80 / 100);
  EXPECT_GE(counts.sense, total * 95 / 100);
  EXPECT_GE(counts.rho_e, kRequests * 80 / 100);
  std::cout << "[ compared ] points " << counts.points << ", R2' " << counts.R2 << ", u_s "
            << counts.u_s << ", v_e " << counts.v_e << ", angle " << counts.angle << ", sense "
            << counts.sense << ", rho_e " << counts.rho_e << " of " << kRequests << "\n";
}

}  // namespace
