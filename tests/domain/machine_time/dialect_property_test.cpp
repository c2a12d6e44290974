// machine-time.md section 4: the same motion written in the three dialects gets the same
// estimate. Random programs of lines and arcs (exact stop, or blended), each written as
// LinuxCNC, Fanuc and Sinumerik would have it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "machine_time_test_support.h"

namespace cutcalc::domain::machine_time {
namespace {

struct Texts {
  std::string linuxcnc;
  std::string fanuc;
  std::string sinumerik;
};

std::string number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3f", v);
  return buffer;
}

Texts random_program(std::mt19937& random, bool exact_stop) {
  Texts t;
  t.linuxcnc = std::string("G21 G90 G17 ") + (exact_stop ? "G61.1" : "G64") + "\n";
  t.fanuc = std::string("%\nO0001 (PROP)\nG21 G90 G17 G94 ") + (exact_stop ? "G61" : "G64") + "\n";
  t.sinumerik = std::string("; PROP\nG71 G90 G17 G94 ") + (exact_stop ? "G60" : "G64") + "\n";
  std::uniform_real_distribution<double> coordinate(-40.0, 40.0);
  std::uniform_int_distribution<int> kind(0, 3);
  std::uniform_int_distribution<int> feed(5, 80);
  double x = 0.0, y = 0.0;
  for (int i = 0; i < 12; ++i) {
    const int k = kind(random);
    const std::string f = " F" + std::to_string(feed(random) * 100);
    if (k == 0) {
      x = std::round(coordinate(random) * 1000) / 1000;
      y = std::round(coordinate(random) * 1000) / 1000;
      const std::string block = "G0 X" + number(x) + " Y" + number(y) + "\n";
      t.linuxcnc += block;
      t.fanuc += block;
      t.sinumerik += block;
    } else if (k == 1) {
      x = std::round(coordinate(random) * 1000) / 1000;
      y = std::round(coordinate(random) * 1000) / 1000;
      const std::string block = "G1 X" + number(x) + " Y" + number(y) + f + "\n";
      t.linuxcnc += block;
      t.fanuc += block;
      t.sinumerik += block;
    } else {
      // A half circle about a centre 5 mm off in X: I/J relative to the start in every dialect.
      const double ex = x + 10.0;
      const std::string g = k == 2 ? "G2" : "G3";
      const std::string block =
          g + " X" + number(ex) + " Y" + number(y) + " I5.000 J0.000" + f + "\n";
      t.linuxcnc += block;
      t.fanuc += block;
      t.sinumerik += block;
      x = ex;
    }
  }
  t.linuxcnc += "M2\n";
  t.fanuc += "M30\n%\n";
  t.sinumerik += "M30\n";
  return t;
}

TEST(DialectProperty, TheSameMotionGetsTheSameEstimateInEveryDialect) {
  std::mt19937 random(20261128);
  for (int trial = 0; trial < 60; ++trial) {
    const Texts t = random_program(random, trial % 2 == 0);
    const double linuxcnc = test::time_of(t.linuxcnc).estimated_s;
    const double fanuc =
        test::time_of(t.fanuc, test::router(), program::Dialect::fanuc).estimated_s;
    const double sinumerik =
        test::time_of(t.sinumerik, test::router(), program::Dialect::sinumerik).estimated_s;
    if (trial % 2 == 0) {
      EXPECT_NEAR(fanuc, linuxcnc, 1e-9 * linuxcnc) << t.linuxcnc << t.fanuc;
    }
    // Blending: Fanuc and Sinumerik G64 name no tolerance, as LinuxCNC's G64 without P.
    EXPECT_NEAR(sinumerik, linuxcnc, 1e-9 * linuxcnc) << t.linuxcnc << t.sinumerik;
    EXPECT_NEAR(fanuc, linuxcnc, 1e-9 * linuxcnc) << t.linuxcnc << t.fanuc;
  }
}

}  // namespace
}  // namespace cutcalc::domain::machine_time
