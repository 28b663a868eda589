// Han (2005)'s cushion with spin, eqs 14–23, typed from the paper in long double with μ in the stick/slip
// test (the paper prints P_zS ≤ P_zE), not from the kernels: the reference of the runtime's test and of
// the fuzz harness for collide_with_cushion.
#pragma once

#include <billiards/shot.hpp>

#include <Eigen/Core>

#include <cmath>

namespace billiards_fuzz {

// Han (2005), eqs 14–23, in the frame where the cushion's normal is x̂ (a rotation by −ψ about ẑ, ψ the
// normal's angle), then rotated back.
template <typename Scalar, typename Long = long double>
billiards::SpinningBall<Long> han_2005(const billiards::SpinningBall<Scalar>& ball,
                                       const billiards::Cushion<Scalar>& cushion, bool* sticks = nullptr) {
  const Long psi = std::atan2(Long(cushion.normal.y()), Long(cushion.normal.x()));
  const Long c_psi = std::cos(psi), s_psi = std::sin(psi);
  using L3 = Eigen::Matrix<Long, 3, 1>;
  const auto to_cushion = [&](const L3& x) { return L3(c_psi * x.x() + s_psi * x.y(), -s_psi * x.x() + c_psi * x.y(), x.z()); };
  const auto to_table = [&](const L3& x) { return L3(c_psi * x.x() - s_psi * x.y(), s_psi * x.x() + c_psi * x.y(), x.z()); };
  L3 v = to_cushion(ball.velocity.template cast<Long>()), w = to_cushion(ball.angular_velocity.template cast<Long>());
  const Long m = ball.mass, R = ball.radius, h = cushion.height, e = cushion.restitution, mu = cushion.friction;
  billiards::SpinningBall<Long> out{ball.velocity.template cast<Long>(), ball.angular_velocity.template cast<Long>(), m, R};
  if (!(v.x() > 0)) return out;
  const Long theta = std::asin(h / R - 1);
  const Long sx = v.x() * std::sin(theta) - v.z() * std::cos(theta) + R * w.y();       // eq. 14
  const Long sy = -v.y() - R * w.z() * std::cos(theta) + R * w.x() * std::sin(theta);  // eq. 14
  const Long c = -v.x() * std::cos(theta);
  const Long II = Long(2) / 5 * m * R * R, A = Long(7) / 2 / m, B = 1 / m;  // eq. 16
  const Long PzE = -(1 + e) * c / B;                                          // eq. 17
  const Long s = std::sqrt(sx * sx + sy * sy);
  const Long PzS = s / A;  // eq. 20
  Long PxE, PyE;
  if (sticks) *sticks = PzS <= mu * PzE;
  if (PzS <= mu * PzE) {  // eq. 18, sticking (Han prints PzS <= PzE)
    PxE = sx / A;
    PyE = sy / A;
  } else {  // eq. 19, sliding
    PxE = mu * PzE * sx / s;
    PyE = mu * PzE * sy / s;
  }
  const Long PX = -PxE * std::sin(theta) - PzE * std::cos(theta), PY = PyE;  // eqs 21, 22
  const Long PZ = PxE * std::cos(theta) - PzE * std::sin(theta);
  v.x() += PX / m;  // eq. 23
  v.y() += PY / m;
  w.x() += -R / II * PY * std::sin(theta);
  w.y() += R / II * (PX * std::sin(theta) - PZ * std::cos(theta));
  w.z() += R / II * PY * std::cos(theta);
  out.velocity = to_table(v);
  out.angular_velocity = to_table(w);
  return out;
}

}  // namespace billiards_fuzz
