// The runtime's checked calls on cases read from stdin, for the Python tests to compare the bindings
// with bit for bit. Input: the call's name and the scalar type ("double" or "float") on the first line,
// then one case a line, its numbers in the order listed below (hexadecimal floating point is read
// exactly). Output: one line a case, the results' numbers in hexadecimal floating point, or "rejected".
#include <billiards/checked.hpp>
#include <billiards/cloth.hpp>
#include <billiards/events.hpp>
#include <billiards/shot.hpp>
#include <billiards/spin.hpp>

#include <Eigen/Core>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace {

template <typename Scalar>
std::vector<Scalar> numbers_of(const std::string& line) {
  std::istringstream in(line);
  std::vector<Scalar> out;
  for (std::string word; in >> word;) out.push_back(static_cast<Scalar>(std::strtod(word.c_str(), nullptr)));
  return out;
}

template <typename Scalar>
void print(const std::vector<Scalar>& values) {
  for (std::size_t k = 0; k < values.size(); ++k)
    std::printf(k ? " %a" : "%a", static_cast<double>(values[k]));
  std::printf("\n");
}

template <typename Scalar, int D>
Eigen::Matrix<Scalar, D, 1> vec(const std::vector<Scalar>& x, std::size_t at) {
  Eigen::Matrix<Scalar, D, 1> v;
  for (int k = 0; k < D; ++k) v[k] = x[at + static_cast<std::size_t>(k)];
  return v;
}

template <typename Scalar, int D>
void append(std::vector<Scalar>& out, const Eigen::Matrix<Scalar, D, 1>& v) {
  for (int k = 0; k < D; ++k) out.push_back(v[k]);
}

// m1 v1[D] m2 v2[D] n[D] e → x1[D] x2[D]
template <typename Scalar, int D>
std::vector<Scalar> collide(const std::vector<Scalar>& x) {
  const auto r = billiards::checked::collide(x[0], vec<Scalar, D>(x, 1), x[1 + D], vec<Scalar, D>(x, 2 + D),
                                             vec<Scalar, D>(x, 2 + 2 * D), x[2 + 3 * D]);
  std::vector<Scalar> out;
  append<Scalar, D>(out, r.first);
  append<Scalar, D>(out, r.second);
  return out;
}

template <typename Scalar>
billiards::SpinningBall<Scalar> ball_at(const std::vector<Scalar>& x, std::size_t at) {
  // mass radius v[3] w[3]
  return {vec<Scalar, 3>(x, at + 2), vec<Scalar, 3>(x, at + 5), x[at], x[at + 1]};
}

template <typename Scalar>
std::vector<Scalar> run(const std::string& name, const std::vector<Scalar>& x) {
  std::vector<Scalar> out;
  if (name == "collide2") return collide<Scalar, 2>(x);
  if (name == "collide3") return collide<Scalar, 3>(x);
  if (name == "collide_with_friction") {  // ball1[8] ball2[8] n[3] e mu
    const auto r = billiards::checked::collide_with_friction(ball_at(x, 0), ball_at(x, 8),
                                                             vec<Scalar, 3>(x, 16), x[19], x[20]);
    for (const auto* b : {&r.first, &r.second}) {
      append<Scalar, 3>(out, b->velocity);
      append<Scalar, 3>(out, b->angular_velocity);
    }
    return out;
  }
  if (name == "strike") {  // ball[8] cue mass speed azimuth elevation a b e_tip
    const auto r = billiards::checked::strike(
        ball_at(x, 0), billiards::Cue<Scalar>{x[8], x[9], x[10], x[11], x[12], x[13], x[14]});
    append<Scalar, 3>(out, r.velocity);
    append<Scalar, 3>(out, r.angular_velocity);
    return out;
  }
  if (name == "collide_with_cushion") {  // ball[8] normal[3] height e mu
    const auto r = billiards::checked::collide_with_cushion(
        ball_at(x, 0), billiards::Cushion<Scalar>{vec<Scalar, 3>(x, 8), x[11], x[12], x[13]});
    append<Scalar, 3>(out, r.velocity);
    append<Scalar, 3>(out, r.angular_velocity);
    return out;
  }
  if (name == "earliest_contact5") {  // c[5] horizon
    const std::array<Scalar, 5> c{x[0], x[1], x[2], x[3], x[4]};
    return {billiards::checked::earliest_contact(c, x[5]).value_or(std::numeric_limits<Scalar>::infinity())};
  }
  if (name == "evolve") {  // position velocity spin radius t μs μr μsp g → position velocity spin
    const billiards::BallOnCloth<Scalar> ball{vec<Scalar, 3>(x, 0), vec<Scalar, 3>(x, 3), vec<Scalar, 3>(x, 6), x[9]};
    const auto later = billiards::checked::evolve(ball, billiards::Cloth<Scalar>{x[11], x[12], x[13], x[14]}, x[10]);
    append<Scalar, 3>(out, later.position);
    append<Scalar, 3>(out, later.velocity);
    append<Scalar, 3>(out, later.angular_velocity);
    return out;
  }
  if (name == "time_of_impact3") {  // p1 v1 p2 v2 distance
    return {billiards::checked::time_of_impact(vec<Scalar, 3>(x, 0), vec<Scalar, 3>(x, 3),
                                               vec<Scalar, 3>(x, 6), vec<Scalar, 3>(x, 9), x[12])};
  }
  throw std::runtime_error("unknown call " + name);
}

template <typename Scalar>
void each_case(const std::string& name) {
  for (std::string line; std::getline(std::cin, line);) {
    try {
      print(run<Scalar>(name, numbers_of<Scalar>(line)));
    } catch (const billiards::invalid_argument&) {
      std::printf("rejected\n");
    }
  }
}

}  // namespace

int main() {
  std::string name, scalar;
  if (!(std::cin >> name >> scalar)) return 2;
  std::string rest;
  std::getline(std::cin, rest);
  if (scalar == "float")
    each_case<float>(name);
  else
    each_case<double>(name);
  return 0;
}
