// The runtime's checked calls over arrays of cases: one loop in C++ per call, without the GIL, each case
// the checked call's result bit for bit. The pure-Python layer (billiards/_runtime.py) broadcasts the
// arguments and reshapes the results.
#include "arrays.hpp"

#include <billiards/checked.hpp>
#include <billiards/cloth.hpp>
#include <billiards/events.hpp>
#include <billiards/shot.hpp>
#include <billiards/spin.hpp>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <string>

namespace billiards::python {
namespace {

template <typename Scalar, int D>
using Vector = Eigen::Matrix<Scalar, D, 1>;
template <typename Scalar, int D>
using Row = Eigen::Map<const Vector<Scalar, D>>;

// Runs `body(i)` for each case i without the GIL, stopping at the first case a checked call rejects.
template <typename Body>
void each_case(py::ssize_t count, Rejection& rejection, Body&& body) {
  py::gil_scoped_release unlocked;
  for (py::ssize_t i = 0; i < count && !rejection.any(); ++i) {
    try {
      body(i);
    } catch (const billiards::invalid_argument& error) {
      rejection.record(static_cast<std::size_t>(i), error);
    }
  }
}

// checked::collide over `count` cases: m1, m2, restitution flat; v1, v2, n rows of D.
template <typename Scalar, int D>
py::tuple collide(const Array<Scalar>& m1, const Array<Scalar>& v1, const Array<Scalar>& m2,
                  const Array<Scalar>& v2, const Array<Scalar>& n, const Array<Scalar>& restitution,
                  bool batch) {
  const py::ssize_t count = m1.shape(0);
  const Scalar *pm1 = rows_of(m1, "m1", count), *pv1 = rows_of(v1, "v1", count, D),
               *pm2 = rows_of(m2, "m2", count), *pv2 = rows_of(v2, "v2", count, D),
               *pn = rows_of(n, "n", count, D), *pe = rows_of(restitution, "restitution", count);
  Array<Scalar> x1 = new_rows<Scalar>(count, D), x2 = new_rows<Scalar>(count, D);
  Scalar *px1 = x1.mutable_data(), *px2 = x2.mutable_data();
  Rejection rejection("collide", batch);
  each_case(count, rejection, [&](py::ssize_t i) {
    const auto after = checked::collide(pm1[i], Row<Scalar, D>(pv1 + D * i), pm2[i],
                                        Row<Scalar, D>(pv2 + D * i), Row<Scalar, D>(pn + D * i), pe[i]);
    Eigen::Map<Vector<Scalar, D>>(px1 + D * i) = after.first;
    Eigen::Map<Vector<Scalar, D>>(px2 + D * i) = after.second;
  });
  rejection.raise_if_any();
  return py::make_tuple(x1, x2);
}

// checked::time_of_impact over `count` cases; +∞ where the spheres never touch.
template <typename Scalar, int D>
Array<Scalar> time_of_impact(const Array<Scalar>& p1, const Array<Scalar>& v1, const Array<Scalar>& p2,
                             const Array<Scalar>& v2, const Array<Scalar>& distance, bool batch) {
  const py::ssize_t count = distance.shape(0);
  const Scalar *pp1 = rows_of(p1, "p1", count, D), *pv1 = rows_of(v1, "v1", count, D),
               *pp2 = rows_of(p2, "p2", count, D), *pv2 = rows_of(v2, "v2", count, D),
               *pd = rows_of(distance, "distance", count);
  Array<Scalar> times = new_rows<Scalar>(count);
  Scalar* pt = times.mutable_data();
  Rejection rejection("time_of_impact", batch, {{"contact_distance", "distance"}});
  each_case(count, rejection, [&](py::ssize_t i) {
    pt[i] = checked::time_of_impact(Row<Scalar, D>(pp1 + D * i), Row<Scalar, D>(pv1 + D * i),
                                    Row<Scalar, D>(pp2 + D * i), Row<Scalar, D>(pv2 + D * i), pd[i]);
  });
  rejection.raise_if_any();
  return times;
}

template <typename Scalar>
SpinningBall<Scalar> spinning_ball(const Scalar* mass, const Scalar* radius, const Scalar* v, const Scalar* w,
                                   py::ssize_t i) {
  return {Row<Scalar, 3>(v + 3 * i), Row<Scalar, 3>(w + 3 * i), mass[i], radius[i]};
}

template <typename Scalar>
void store(const SpinningBall<Scalar>& ball, Scalar* v, Scalar* w, py::ssize_t i) {
  Eigen::Map<Vector<Scalar, 3>>(v + 3 * i) = ball.velocity;
  Eigen::Map<Vector<Scalar, 3>>(w + 3 * i) = ball.angular_velocity;
}

// checked::collide_with_friction: two spinning balls; returns v1, w1, v2, w2 after.
template <typename Scalar>
py::tuple collide_with_friction(const Array<Scalar>& m1, const Array<Scalar>& r1, const Array<Scalar>& v1,
                                const Array<Scalar>& w1, const Array<Scalar>& m2, const Array<Scalar>& r2,
                                const Array<Scalar>& v2, const Array<Scalar>& w2, const Array<Scalar>& n,
                                const Array<Scalar>& restitution, const Array<Scalar>& friction, bool batch) {
  const py::ssize_t count = m1.shape(0);
  const Scalar *pm1 = rows_of(m1, "m1", count), *pr1 = rows_of(r1, "radius1", count),
               *pv1 = rows_of(v1, "v1", count, 3), *pw1 = rows_of(w1, "w1", count, 3),
               *pm2 = rows_of(m2, "m2", count), *pr2 = rows_of(r2, "radius2", count),
               *pv2 = rows_of(v2, "v2", count, 3), *pw2 = rows_of(w2, "w2", count, 3),
               *pn = rows_of(n, "n", count, 3), *pe = rows_of(restitution, "restitution", count),
               *pf = rows_of(friction, "friction", count);
  std::array<Array<Scalar>, 4> out{new_rows<Scalar>(count, 3), new_rows<Scalar>(count, 3),
                                   new_rows<Scalar>(count, 3), new_rows<Scalar>(count, 3)};
  Scalar *ov1 = out[0].mutable_data(), *ow1 = out[1].mutable_data(), *ov2 = out[2].mutable_data(),
         *ow2 = out[3].mutable_data();
  Rejection rejection("collide_with_friction", batch,
                      {{"ball1.mass", "m1"},
                       {"ball1.radius", "radius1"},
                       {"ball1.velocity", "v1"},
                       {"ball1.angular_velocity", "w1"},
                       {"ball2.mass", "m2"},
                       {"ball2.radius", "radius2"},
                       {"ball2.velocity", "v2"},
                       {"ball2.angular_velocity", "w2"},
                       {"ball1, ball2", "m1, m2, radius1, radius2"}});
  each_case(count, rejection, [&](py::ssize_t i) {
    const auto after = checked::collide_with_friction(spinning_ball(pm1, pr1, pv1, pw1, i),
                                                      spinning_ball(pm2, pr2, pv2, pw2, i),
                                                      Row<Scalar, 3>(pn + 3 * i), pe[i], pf[i]);
    store(after.first, ov1, ow1, i);
    store(after.second, ov2, ow2, i);
  });
  rejection.raise_if_any();
  return py::make_tuple(out[0], out[1], out[2], out[3]);
}

// checked::strike: the ball (mass, radius, v, w) struck by the cue whose parameters are the rows of
// `cue` (mass, speed, azimuth, elevation, side_offset, up_offset, tip_restitution); returns v, w after.
template <typename Scalar>
py::tuple strike(const Array<Scalar>& mass, const Array<Scalar>& radius, const Array<Scalar>& v,
                 const Array<Scalar>& w, const Array<Scalar>& cue, bool batch) {
  const py::ssize_t count = mass.shape(0);
  const Scalar *pm = rows_of(mass, "mass", count), *pr = rows_of(radius, "radius", count),
               *pv = rows_of(v, "velocity", count, 3), *pw = rows_of(w, "angular_velocity", count, 3),
               *pc = rows_of(cue, "cue", count, 7);
  Array<Scalar> v_after = new_rows<Scalar>(count, 3), w_after = new_rows<Scalar>(count, 3);
  Scalar *ov = v_after.mutable_data(), *ow = w_after.mutable_data();
  Rejection rejection("strike", batch,
                      {{"ball.mass", "mass"},
                       {"ball.radius", "radius"},
                       {"ball.velocity", "velocity"},
                       {"ball.angular_velocity", "angular_velocity"},
                       {"cue.mass", "cue_mass"},
                       {"cue.speed", "speed"},
                       {"cue.azimuth", "azimuth"},
                       {"cue.elevation", "elevation"},
                       {"cue.side_offset", "side_offset"},
                       {"cue.up_offset", "up_offset"},
                       {"cue.tip_restitution", "tip_restitution"}});
  each_case(count, rejection, [&](py::ssize_t i) {
    const Scalar* c = pc + 7 * i;
    store(checked::strike(spinning_ball(pm, pr, pv, pw, i),
                          Cue<Scalar>{c[0], c[1], c[2], c[3], c[4], c[5], c[6]}),
          ov, ow, i);
  });
  rejection.raise_if_any();
  return py::make_tuple(v_after, w_after);
}

// checked::collide_with_cushion: the ball (mass, radius, v, w) against the cushion whose normal is a
// row of `normal` and whose height, restitution and friction are `cushion`'s rows; returns v, w after.
template <typename Scalar>
py::tuple collide_with_cushion(const Array<Scalar>& mass, const Array<Scalar>& radius, const Array<Scalar>& v,
                               const Array<Scalar>& w, const Array<Scalar>& normal,
                               const Array<Scalar>& cushion, bool batch) {
  const py::ssize_t count = mass.shape(0);
  const Scalar *pm = rows_of(mass, "mass", count), *pr = rows_of(radius, "radius", count),
               *pv = rows_of(v, "velocity", count, 3), *pw = rows_of(w, "angular_velocity", count, 3),
               *pn = rows_of(normal, "normal", count, 3), *pc = rows_of(cushion, "cushion", count, 3);
  Array<Scalar> v_after = new_rows<Scalar>(count, 3), w_after = new_rows<Scalar>(count, 3);
  Scalar *ov = v_after.mutable_data(), *ow = w_after.mutable_data();
  Rejection rejection("collide_with_cushion", batch,
                      {{"ball.mass", "mass"},
                       {"ball.radius", "radius"},
                       {"ball.velocity", "velocity"},
                       {"ball.angular_velocity", "angular_velocity"},
                       {"cushion.normal", "normal"},
                       {"cushion.height", "height"},
                       {"cushion.restitution", "restitution"},
                       {"cushion.friction", "friction"}});
  each_case(count, rejection, [&](py::ssize_t i) {
    const Scalar* c = pc + 3 * i;
    store(checked::collide_with_cushion(spinning_ball(pm, pr, pv, pw, i),
                                        Cushion<Scalar>{Row<Scalar, 3>(pn + 3 * i), c[0], c[1], c[2]}),
          ov, ow, i);
  });
  rejection.raise_if_any();
  return py::make_tuple(v_after, w_after);
}

// checked::earliest_contact over rows of N coefficients (c0 … c_{N−1}); +∞ where there is no contact.
template <typename Scalar, std::size_t N>
Array<Scalar> earliest_contact(const Array<Scalar>& coefficients, const Array<Scalar>& horizon, bool batch) {
  const py::ssize_t count = horizon.shape(0);
  const Scalar *pc = rows_of(coefficients, "coefficients", count, static_cast<py::ssize_t>(N)),
               *ph = rows_of(horizon, "horizon", count);
  Array<Scalar> times = new_rows<Scalar>(count);
  Scalar* pt = times.mutable_data();
  Rejection rejection("earliest_contact", batch);
  each_case(count, rejection, [&](py::ssize_t i) {
    std::array<Scalar, N> c;
    for (std::size_t k = 0; k < N; ++k) c[k] = pc[N * static_cast<std::size_t>(i) + k];
    pt[i] = checked::earliest_contact(c, ph[i]).value_or(std::numeric_limits<Scalar>::infinity());
  });
  rejection.raise_if_any();
  return times;
}

// The balls on the cloth of `count` cases: centre, velocity and spin rows of 3, radius flat.
template <typename Scalar>
BallOnCloth<Scalar> ball_on_cloth(const Scalar* p, const Scalar* v, const Scalar* w, const Scalar* r,
                                  py::ssize_t i) {
  return {Row<Scalar, 3>(p + 3 * i), Row<Scalar, 3>(v + 3 * i), Row<Scalar, 3>(w + 3 * i), r[i]};
}

template <typename Scalar>
Cloth<Scalar> cloth_of(const Scalar* c, py::ssize_t i) {
  return {c[4 * i], c[4 * i + 1], c[4 * i + 2], c[4 * i + 3]};
}

const std::map<std::string, std::string>& cloth_names() {
  static const std::map<std::string, std::string> names{{"ball.position", "position"},
                                                        {"ball.velocity", "velocity"},
                                                        {"ball.angular_velocity", "angular_velocity"},
                                                        {"ball.radius", "radius"}};
  return names;
}

// checked::evolve: the balls after t on the cloth whose rows are (μ_s, μ_r, μ_sp, g); returns the centre,
// velocity and spin.
template <typename Scalar>
py::tuple evolve(const Array<Scalar>& position, const Array<Scalar>& velocity, const Array<Scalar>& spin,
                 const Array<Scalar>& radius, const Array<Scalar>& t, const Array<Scalar>& cloth,
                 bool batch) {
  const py::ssize_t count = radius.shape(0);
  const Scalar *pp = rows_of(position, "position", count, 3), *pv = rows_of(velocity, "velocity", count, 3),
               *pw = rows_of(spin, "angular_velocity", count, 3), *pr = rows_of(radius, "radius", count),
               *pt = rows_of(t, "t", count), *pc = rows_of(cloth, "cloth", count, 4);
  std::array<Array<Scalar>, 3> out{new_rows<Scalar>(count, 3), new_rows<Scalar>(count, 3),
                                   new_rows<Scalar>(count, 3)};
  Scalar *op = out[0].mutable_data(), *ov = out[1].mutable_data(), *ow = out[2].mutable_data();
  Rejection rejection("evolve", batch, cloth_names());
  each_case(count, rejection, [&](py::ssize_t i) {
    const BallOnCloth<Scalar> later =
        checked::evolve(ball_on_cloth(pp, pv, pw, pr, i), cloth_of(pc, i), pt[i]);
    Eigen::Map<Vector<Scalar, 3>>(op + 3 * i) = later.position;
    Eigen::Map<Vector<Scalar, 3>>(ov + 3 * i) = later.velocity;
    Eigen::Map<Vector<Scalar, 3>>(ow + 3 * i) = later.angular_velocity;
  });
  rejection.raise_if_any();
  return py::make_tuple(out[0], out[1], out[2]);
}

// checked::motion and checked::transition_time: each ball's phase (billiards::Motion's value) and how
// long it lasts.
template <typename Scalar>
py::tuple phase(const Array<Scalar>& position, const Array<Scalar>& velocity, const Array<Scalar>& spin,
                const Array<Scalar>& radius, const Array<Scalar>& cloth, bool batch) {
  const py::ssize_t count = radius.shape(0);
  const Scalar *pp = rows_of(position, "position", count, 3), *pv = rows_of(velocity, "velocity", count, 3),
               *pw = rows_of(spin, "angular_velocity", count, 3), *pr = rows_of(radius, "radius", count),
               *pc = rows_of(cloth, "cloth", count, 4);
  py::array_t<std::int8_t> motion(std::vector<py::ssize_t>{count});
  Array<Scalar> duration = new_rows<Scalar>(count);
  std::int8_t* om = motion.mutable_data();
  Scalar* od = duration.mutable_data();
  Rejection rejection("transition_time", batch, cloth_names());
  each_case(count, rejection, [&](py::ssize_t i) {
    const BallOnCloth<Scalar> ball = ball_on_cloth(pp, pv, pw, pr, i);
    om[i] = static_cast<std::int8_t>(checked::motion(ball, cloth_of(pc, i)));
    od[i] = checked::transition_time(ball, cloth_of(pc, i));
  });
  rejection.raise_if_any();
  return py::make_tuple(motion, duration);
}

template <typename Scalar>
void bind_scalar(py::module_& m) {
  m.def("collide2", &collide<Scalar, 2>);
  m.def("collide3", &collide<Scalar, 3>);
  m.def("time_of_impact2", &time_of_impact<Scalar, 2>);
  m.def("time_of_impact3", &time_of_impact<Scalar, 3>);
  m.def("collide_with_friction", &collide_with_friction<Scalar>);
  m.def("strike", &strike<Scalar>);
  m.def("collide_with_cushion", &collide_with_cushion<Scalar>);
  m.def("earliest_contact3", &earliest_contact<Scalar, 3>);
  m.def("earliest_contact5", &earliest_contact<Scalar, 5>);
  m.def("evolve", &evolve<Scalar>);
  m.def("phase", &phase<Scalar>);
}

}  // namespace

void bind_runtime(py::module_& m) {
  // One overload per dtype, the exact one first: pybind11 tries them in order, and the Python layer
  // hands over arrays of one dtype, so no argument is converted.
  bind_scalar<double>(m);
  bind_scalar<float>(m);
  m.def("component_limit", [](const std::string& dtype) {
    return dtype == "float32" ? static_cast<double>(component_limit<float>()) : component_limit<double>();
  });
}

}  // namespace billiards::python
