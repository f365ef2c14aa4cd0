// The coil's two-node heat balance against its closed forms.
#include "tendril/physics/twins/sma/coil_thermal.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/error_message.hpp"

namespace tendril::physics {
namespace {

// With the silicone node all but disconnected the wire is a first-order system:
// T_w(t) = T_a + (P / g_wa)(1 − e^{−t/τ}), τ = C_w / g_wa — the step response.
TEST(CoilThermal, AnIsolatedWireFollowsTheFirstOrderStepResponse) {
  CoilThermalSpec spec;
  spec.wire_to_body = 1e-12;
  const CoilThermal thermal(spec);
  const double power = spec.power(0.15);
  EXPECT_NEAR(power, 0.15 * 11.1 * 11.1 / spec.resistance, 1e-12);
  const double tau = spec.wire_capacity / spec.wire_to_ambient;
  double wire = spec.ambient_temperature, body = spec.ambient_temperature;
  double t = 0.0;
  for (double h : {0.5, 1.0, 3.0, 10.0, 50.0}) {
    thermal.advance(wire, body, power, h);
    t += h;
    const double expected =
        spec.ambient_temperature + power / spec.wire_to_ambient * (1.0 - std::exp(-t / tau));
    EXPECT_NEAR(wire, expected, 1e-9 * expected) << "t = " << t;
  }
  EXPECT_NEAR(body, spec.ambient_temperature, 1e-6);
}

// The steady state solves the two balances by hand: T_b − T_a = g_wb (T_w − T_a) / (g_wb + g_ba)
// and P = g_wa (T_w − T_a) + g_wb (T_w − T_b).
TEST(CoilThermal, SettlesToTheSteadyStateOfBothBalances) {
  const CoilThermalSpec spec;
  const CoilThermal thermal(spec);
  const double power = 0.4;
  const double share = spec.wire_to_body / (spec.wire_to_body + spec.body_to_ambient);
  const double wire_excess = power / (spec.wire_to_ambient + spec.wire_to_body * (1.0 - share));
  const Eigen::Vector2d steady = thermal.steady_state(power);
  EXPECT_NEAR(steady[0] - spec.ambient_temperature, wire_excess, 1e-9 * wire_excess);
  EXPECT_NEAR(steady[1] - spec.ambient_temperature, share * wire_excess, 1e-9 * wire_excess);
  double wire = spec.ambient_temperature, body = spec.ambient_temperature;
  thermal.advance(wire, body, power, 5000.0);
  EXPECT_NEAR(wire, steady[0], 1e-9 * steady[0]);
  EXPECT_NEAR(body, steady[1], 1e-9 * steady[1]);
}

// Cooling is the sum of two exponentials whose rates are the eigenvalues of
// A = [[−(g_wa + g_wb)/C_w, g_wb/C_w], [g_wb/C_b, −(g_wb + g_ba)/C_b]], by the quadratic formula;
// once the fast one has died out, the excess shrinks by e^{−Δ/τ_slow} every Δ.
TEST(CoilThermal, CoolsWithTheNetworksTwoTimeConstants) {
  const CoilThermalSpec spec;
  const CoilThermal thermal(spec);
  const double a = -(spec.wire_to_ambient + spec.wire_to_body) / spec.wire_capacity;
  const double b = spec.wire_to_body / spec.wire_capacity;
  const double c = spec.wire_to_body / spec.body_capacity;
  const double d = -(spec.wire_to_body + spec.body_to_ambient) / spec.body_capacity;
  const double half_trace = 0.5 * (a + d), det = a * d - b * c;
  const double fast = -1.0 / (half_trace - std::sqrt(half_trace * half_trace - det));
  const double slow = -1.0 / (half_trace + std::sqrt(half_trace * half_trace - det));
  EXPECT_NEAR(thermal.time_constants()[0], fast, 1e-12 * fast);
  EXPECT_NEAR(thermal.time_constants()[1], slow, 1e-12 * slow);
  // The design targets: a wire of a second or two, silicone of about a minute.
  EXPECT_GT(fast, 1.0);
  EXPECT_LT(fast, 3.0);
  EXPECT_GT(slow, 45.0);
  EXPECT_LT(slow, 75.0);

  double wire = 110.0, body = 40.0;
  thermal.advance(wire, body, 0.0, 30.0);  // e^{−30/τ_fast} < 1e-6
  const double excess = wire - spec.ambient_temperature;
  thermal.advance(wire, body, 0.0, 20.0);
  EXPECT_NEAR((wire - spec.ambient_temperature) / excess, std::exp(-20.0 / slow), 1e-4);
}

// Exact stepping: one step of h equals many steps that add up to h (constant power).
TEST(CoilThermal, StepsComposeExactly) {
  const CoilThermalSpec spec;
  const CoilThermal thermal(spec);
  double wire_one = 30.0, body_one = 25.0, wire_many = 30.0, body_many = 25.0;
  thermal.advance(wire_one, body_one, 1.2, 2.5);
  for (int k = 0; k < 1250; ++k) thermal.advance(wire_many, body_many, 1.2, 0.002);
  EXPECT_NEAR(wire_many, wire_one, 1e-9);
  EXPECT_NEAR(body_many, body_one, 1e-9);
}

// What Fig. 1.1c of the thesis needs: after the coil was driven for 40 s at the stiff limb's
// upper bound (15 % duty), the wire is back near the silicone within seconds, but the silicone
// still holds more than 40 % of its excess heat 30 s later, and less than 6 % after 180 s.
TEST(CoilThermal, ThirtySecondsLeaveTheSiliconeWarmAndThreeMinutesDoNot) {
  const CoilThermalSpec spec;
  const CoilThermal thermal(spec);
  double wire = spec.ambient_temperature, body = spec.ambient_temperature;
  thermal.advance(wire, body, spec.power(0.15), 40.0);
  const double heated = body - spec.ambient_temperature;
  ASSERT_GT(heated, 20.0);
  double wire_30 = wire, body_30 = body, wire_180 = wire, body_180 = body;
  thermal.advance(wire_30, body_30, 0.0, 30.0);
  thermal.advance(wire_180, body_180, 0.0, 180.0);
  EXPECT_GT((body_30 - spec.ambient_temperature) / heated, 0.4);
  EXPECT_LT(wire_30 - body_30, 0.05 * (wire - spec.ambient_temperature));
  EXPECT_LT((body_180 - spec.ambient_temperature) / heated, 0.06);
  EXPECT_LT((wire_180 - spec.ambient_temperature) / heated, 0.06);
}

TEST(CoilThermal, InvalidSpecsAreNamed) {
  CoilThermalSpec spec;
  spec.body_capacity = 0.0;
  EXPECT_NE(testing::error_message([&] { CoilThermal thermal(spec); }).find("body_capacity"),
            std::string::npos);
}

}  // namespace
}  // namespace tendril::physics
