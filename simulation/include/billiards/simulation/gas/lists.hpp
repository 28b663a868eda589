// The gas's neighbour-list engine, for any radii and masses: each ball keeps a list of the balls whose
// centres were within shell (r_i + r_j) of its own when the later of the two lists was built, and its
// next event is the earlier of its earliest collision with a ball of its list and the rebuild of its
// list, due when it has moved (shell − 1) r_i from where the list was built. Used by Gas (gas.hpp),
// which documents the choice between engines.
#pragma once

#include <billiards/simulation/gas/engine.hpp>
#include <billiards/simulation/core/large_array.hpp>
#include <billiards/simulation/core/prefetch.hpp>

#include <billiards/collision.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace billiards::simulation::detail {

template <int D>
class ListGas : public GasEngine<D, ListGas<D>> {
  using Base = GasEngine<D, ListGas<D>>;
  friend Base;

 public:
  using typename Base::Vector;
  using Base::nearest_image;
  static constexpr bool lists = true;
  // How far a list reaches: ball j is on ball i's list when their centres were closer than shell (r_i +
  // r_j) when the later of the two lists was built.
  static constexpr double shell = 1.5;

  ListGas(const GasSetup<D>& setup, std::uint64_t max_events_without_collision)
      : Base(setup, max_events_without_collision) {
    const std::size_t n = setup.balls.size();
    double largest = 0;
    for (std::size_t i = 0; i < n; ++i) largest = std::max(largest, setup.radius_of(i));
    // Cells at least one list's reach wide, shell times the largest diameter: a ball's neighbours lie
    // in the 3^D cells around its own. Fewer than three a side would search a cell twice: one cell.
    // The reach then widened to the cells' width, up to 1.25 shell: a rebuild searches those cells
    // anyway, and a longer reach is rebuilt less often.
    const int per_side = gas::grid_cells_per_side(D, n, side_ / (shell_ * 2 * largest));
    this->lay_out_cells(per_side < 3 ? 1 : per_side);
    if (per_side >= 3) shell_ = std::min(1.25 * shell, this->cell_width_ / (2 * largest));
    ball_.resize(n);
    own_.resize(n);
    head_.assign(head_.size(), 0);  // here each cell's count of slots
    slot_.assign(head_.size() * slots_, Slot{});
    capacity_ = D == 2 ? 16 : 32;
    neighbour_.assign(n * capacity_, 0);
    for (std::size_t i = 0; i < n; ++i) {
      Ball& b = ball_[i];
      b.position = setup.balls[i].position;
      b.velocity = setup.balls[i].velocity;
      b.radius = setup.radius_of(i);
      own_[i].mass = setup.mass_of(i);
      for (int k = 0; k < D; ++k) b.position[k] = this->into_box(b.position[k]);
      own_[i].centre = b.position;
      file(i, cell_of(b.position));
    }
    for (std::size_t i = 0; i < n; ++i) find_neighbours(i, /*later_only=*/true);
    check_no_overlap();
    for (std::size_t i = 0; i < n; ++i) predict_event(i);
    calendar_.defer_filings(n >= look_ahead_from);
    this->refile();
    this->reset_measurements();
  }

  // What the base reads of ball i.
  const Vector& velocity(std::size_t i) const { return ball_[i].velocity; }
  double mass_of(std::size_t i) const { return own_[i].mass; }
  double radius_of(std::size_t i) const { return ball_[i].radius; }
  Vector position_now(std::size_t i) const { return ball_[i].position + ball_[i].velocity * (now_ - ball_[i].updated); }
  double event_time(std::size_t i) const { return own_[i].time; }

 private:
  using typename Base::Cell;
  using typename Base::Wraps;
  using Base::none;
  using Base::infinity;
  using Base::side_;
  using Base::now_;
  using Base::cells_per_side_;
  using Base::axis_offset_;
  using Base::head_;
  using Base::identity_;
  using Base::wraps_;
  using Base::calendar_;
  using Base::collision_number_;
  using Base::since_refile_;
  using Base::wrapped;
  using Base::cell_coordinates;

  // No two balls closer than the sum of their radii (less 1e-9 of it) on their nearest images: every
  // pair that close is on the neighbour lists, which hold every pair within shell (r_i + r_j).
  void check_no_overlap() const;

  std::size_t cell_of(const Vector& x) const { return this->cell_index(cell_coordinates(x)); }
  // Files ball i's list centre and radius in the slots of cell c, making room where the cell is full
  // (every cell's slots doubled).
  void file(std::size_t i, std::size_t c) {
    if (head_[c] == slots_) widen_cells();
    slot_[c * slots_ + head_[c]++] = Slot{own_[i].centre, ball_[i].radius, static_cast<std::uint32_t>(i)};
    own_[i].cell = static_cast<std::uint32_t>(c);
  }
  // Takes ball i out of its cell's slots.
  void unfile(std::size_t i) {
    const std::size_t c = own_[i].cell;
    Slot* slots = &slot_[c * slots_];
    for (std::uint32_t k = 0, count = head_[c]; k < count; ++k) {
      if (slots[k].ball == i) {
        slots[k] = slots[--head_[c]];
        return;
      }
    }
  }
  void widen_cells() {
    const std::size_t wider = 2 * slots_;
    detail::Array<Slot> slots(head_.size() * wider, Slot{});
    for (std::size_t c = 0; c < head_.size(); ++c) std::copy_n(&slot_[c * slots_], head_[c], &slots[c * wider]);
    slot_.swap(slots);
    slots_ = wider;
  }

  void bring_to_now(std::size_t i) {
    ball_[i].position += ball_[i].velocity * (now_ - ball_[i].updated);
    ball_[i].updated = now_;
  }

  // Ball i's list: its count of neighbours, then the neighbours, capacity_ entries in all from
  // i capacity_, so that an event's first touch of the list brings its count along.
  std::uint32_t& count_of(std::size_t i) { return neighbour_[i * capacity_]; }
  std::uint32_t count_of(std::size_t i) const { return neighbour_[i * capacity_]; }
  std::uint32_t* list_of(std::size_t i) { return &neighbour_[i * capacity_ + 1]; }
  const std::uint32_t* list_of(std::size_t i) const { return &neighbour_[i * capacity_ + 1]; }

  // Puts j on ball i's list, making room where the list is full (every list's capacity doubled).
  void add_neighbour(std::size_t i, std::size_t j) {
    if (count_of(i) + 1 == capacity_) grow();
    list_of(i)[count_of(i)++] = static_cast<std::uint32_t>(j);
  }
  void grow() {
    const std::size_t wider = 2 * capacity_;
    detail::Array<std::uint32_t> lists(ball_.size() * wider, 0);
    for (std::size_t i = 0; i < ball_.size(); ++i) {
      std::copy_n(&neighbour_[i * capacity_], count_of(i) + 1, &lists[i * wider]);
    }
    neighbour_.swap(lists);
    capacity_ = wider;
  }
  // Takes j off ball i's list.
  void drop_neighbour(std::size_t i, std::size_t j) {
    std::uint32_t* list = list_of(i);
    std::uint32_t& count = count_of(i);
    for (std::uint32_t k = 0; k < count; ++k) {
      if (list[k] == j) {
        list[k] = list[--count];
        return;
      }
    }
  }

  // Ball i's neighbours: every ball of the cells around its own whose list centre is closer to its own
  // than shell (r_i + r_j) on their nearest images, put on both lists (`later_only`: only balls
  // numbered after i, for the first lists, built ball by ball).
  void find_neighbours(std::size_t i, bool later_only);

  // Ball i's list built anew around where it is now: it leaves its old neighbours' lists, moves to the
  // cell of its new centre (its position now, taken into the box) and finds its neighbours there.
  void rebuild(std::size_t i) {
    bring_to_now(i);
    Ball& b = ball_[i];
    for (int k = 0; k < D; ++k) {
      if (b.position[k] >= side_) {
        b.position[k] -= side_;
        ++wraps_[i][k];
      } else if (b.position[k] < 0) {
        b.position[k] += side_;
        --wraps_[i][k];
      }
      if (!(b.position[k] >= 0 && b.position[k] < side_)) b.position[k] = this->into_box(b.position[k]);
    }
    const std::uint32_t* list = list_of(i);
    for (std::uint32_t k = 0; k < count_of(i); ++k) drop_neighbour(list[k], i);
    count_of(i) = 0;
    unfile(i);
    own_[i].centre = b.position;
    file(i, cell_of(b.position));
    find_neighbours(i, false);
  }

  // How far ball i may move from its list's centre before its list is rebuilt: (shell − 1) r_i, less
  // 2^-20 of it so that rounding never lets a neighbour's contact go unlisted.
  double leeway(std::size_t i) const { return (shell_ - 1) * ball_[i].radius * (1 - 0x1p-20); }

  // Ball i's next event, from now (ball i brought to now): the earliest predicted collision with a ball
  // of its list, or the rebuild of its list when it has moved its leeway from the list's centre.
  void predict_event(std::size_t i) {
    const Ball& bi = ball_[i];
    Own& own = own_[i];
    // The rebuild: |x + v t − c| = leeway, the later root.
    const Vector d = bi.position - own.centre;
    const double v2 = bi.velocity.squaredNorm(), reach = leeway(i);
    double best = infinity;
    if (v2 > 0) {
      const double b = d.dot(bi.velocity), disc = b * b - v2 * (d.squaredNorm() - reach * reach);
      best = disc > 0 ? std::max(0.0, (std::sqrt(disc) - b) / v2) : 0.0;
    }
    std::uint32_t partner = none;
    const std::uint32_t* list = list_of(i);
    const std::uint32_t count = count_of(i);
    const double half = side_ / 2;
    for (std::uint32_t k = 0; k < count; ++k) {
      const std::uint32_t j = list[k];
      const Ball& bj = ball_[j];
      const double since = now_ - bj.updated;
      Vector p, dv;
      double approach = 0, squared = 0;
      for (int a = 0; a < D; ++a) {
        // The nearest image without branches: a neighbour is as likely on one side as the other.
        double x = bj.position[a] + bj.velocity[a] * since - bi.position[a];
        x -= side_ * (static_cast<double>(x > half) - static_cast<double>(x < -half));
        p[a] = x;
        dv[a] = bj.velocity[a] - bi.velocity[a];
        approach += x * dv[a];
        squared += x * x;
      }
      const double contact = bi.radius + bj.radius;
      // Passed over, in one test (one branch, mostly taken the same way): a pair moving apart, which
      // never meets (time_of_impact would say +∞), and a pair that cannot meet before the best time so
      // far: the gap |p|² − contact² closes no faster than −2 (p·dv) t (|p + dv t|² ≥ |p|² + 2 p·dv t;
      // the bound loosened by 2^-40 of itself against rounding).
      const bool apart = approach >= 0;
      const bool later = squared - contact * contact > -2 * approach * best * (1 + 0x1p-40);
      if (apart | later) continue;
      const double t = billiards::time_of_impact(Vector::Zero().eval(), bi.velocity, p, bj.velocity, contact);
      if (t < best) {
        best = t;
        partner = j;
      }
    }
    own.time = now_ + best;
    own.partner = partner;
    own.predicted_after = collision_number_;
  }

  // Renumbers the balls in the order of their list centres' cells, so that balls near in space are
  // near in memory (a gas mixes them, and beyond the caches every prediction would otherwise miss
  // them). Nothing physical changes: every ball is brought to now on its own line, and the events keep
  // their times, with partners and neighbours renumbered, filed anew in the calendar.
  void reorder();
  template <class Array>
  static void permute(Array& records, Array& spare, const std::vector<std::uint32_t>& order) {
    spare.resize(records.size());
    for (std::size_t k = 0; k < order.size(); ++k) spare[k] = records[order[k]];
    records.swap(spare);
  }

  // Asks memory for what the next events will read, so that their misses overlap this event's work
  // instead of following it (the calendar's look ahead), each a bucket after what it reads was asked
  // for: for the balls three buckets ahead their records and lists; two ahead their neighbours'
  // records, which their predictions read, and their partners' records and lists; one ahead the
  // partners' neighbours' records.
  void prefetch_next_events();
  // What the rebuild of ball k's list writes and reads: its neighbours' lists, which it leaves, and the
  // 3^D cells around where it will be, their counts and first slots.
  void prefetch_rebuild(std::size_t k) const {
    const std::uint32_t* list = list_of(k);
    for (std::uint32_t m = 0, count = count_of(k); m < count; ++m) detail::prefetch(&neighbour_[list[m] * capacity_]);
    if (cells_per_side_ < 3) return;
    const Ball& b = ball_[k];
    std::size_t part[D][3];
    for (int a = 0; a < D; ++a) {
      double x = b.position[a] + b.velocity[a] * (own_[k].time - b.updated);
      x = x < 0 ? x + side_ : x >= side_ ? x - side_ : x;
      const int c = std::clamp(static_cast<int>(x / this->cell_width_), 0, cells_per_side_ - 1);
      for (int step = -1; step <= 1; ++step) part[a][step + 1] = axis_offset_[a][static_cast<std::size_t>(wrapped(c + step))];
    }
    const auto ask = [&](std::size_t cell) {
      detail::prefetch(&head_[cell]);
      detail::prefetch(&slot_[cell * slots_]);
    };
    if constexpr (D == 2) {
      for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x) ask(part[1][y] + part[0][x]);
    } else {
      for (int z = 0; z < 3; ++z)
        for (int y = 0; y < 3; ++y)
          for (int x = 0; x < 3; ++x) ask(part[2][z] + part[1][y] + part[0][x]);
    }
  }
  void prefetch_neighbours(std::size_t k) const {
    const std::uint32_t* list = list_of(k);
    for (std::uint32_t m = 0, count = count_of(k); m < count; ++m) detail::prefetch(&ball_[list[m]]);
  }

  // Beyond the caches: asks memory for what filing ball i at its event time will read.
  void prefetch_filing(std::size_t i) {
    if (ball_.size() >= look_ahead_from) calendar_.prefetch_update(static_cast<std::uint32_t>(i), own_[i].time);
  }

  // Runs events until `collisions` more collisions or until the next event lies beyond `until`, calling
  // `on_collision` after each collision; returns the collisions run (GasEngine::run_events picks
  // `beyond_caches`: the look ahead of prefetch_next_events).
  template <bool beyond_caches, typename OnCollision>
  std::uint64_t run_all(std::uint64_t collisions, double until, OnCollision& on_collision) {
    std::uint64_t quiet = 0, done = 0;
    while (done < collisions) {
      const std::uint32_t earliest = calendar_.earliest();
      if (earliest == EventCalendar::none) {
        break;  // no event ever: the run ends here (at `until`, where it is finite)
      }
      const std::size_t i = earliest;
      Own& own = own_[i];
      if (own.time > until) break;
      if constexpr (beyond_caches) prefetch_next_events();
      now_ = own.time;
      if (own.partner == none) {  // the list's rebuild
        rebuild(i);
        ++this->own_events_;
        predict_event(i);
        calendar_.update(static_cast<std::uint32_t>(i), own.time);
      } else if (own_[own.partner].last_collision > own.predicted_after) {
        bring_to_now(i);  // stale: the partner has collided since
        predict_event(i);
        calendar_.update(static_cast<std::uint32_t>(i), own.time);
      } else {
        const std::size_t j = own.partner;
        // The partner leaves its place in the calendar's lists: asked of memory now, written below.
        if constexpr (beyond_caches) calendar_.prefetch_removal(static_cast<std::uint32_t>(j));
        bring_to_now(i);
        bring_to_now(j);
        Ball& bi = ball_[i];
        Ball& bj = ball_[j];
        const Vector image = bi.position + nearest_image(bi.position, bj.position);
        const double contact = bi.radius + bj.radius;
        this->measure_contact((image - bi.position).norm(), contact);
        const double mi = own.mass, mj = own_[j].mass;
        const auto [vi, vj] =
            billiards::collide_if_approaching(mi, bi.position, bi.velocity, mj, image, bj.velocity);
        const Vector change = vi - bi.velocity;
        const bool changed = !(vi.array() == bi.velocity.array()).all();
        bi.velocity = vi;
        bj.velocity = vj;
        own.last_collision = own_[j].last_collision = ++collision_number_;
        // Both predicted before either is filed, each filing asked of memory ahead of it.
        predict_event(i);
        prefetch_filing(i);
        predict_event(j);
        prefetch_filing(j);
        calendar_.update(static_cast<std::uint32_t>(i), own.time);
        calendar_.update(static_cast<std::uint32_t>(j), own_[j].time);
        if (changed) {
          this->count_collision(bi.position - image, change, mi, mj, contact);
          ++done;
          quiet = 0;
          on_collision(GasEvent{now_, GasEvent::Kind::ball, identity_[i], identity_[j]});
          this->refile_now_and_then();
        }
      }
      this->count_quiet(quiet);
    }
    return done;
  }

  double shell_ = shell;
  // What a prediction reads of each neighbour, in one place (one cache line): its position at its last
  // update, that time, its velocity, its radius.
  struct alignas(64) Ball {
    Vector position = Vector::Zero();
    double updated = 0;
    Vector velocity = Vector::Zero();
    double radius = 0.5;
  };
  detail::Array<Ball> ball_;
  // What an event reads of its own ball: its next event's time and partner (none: the list's rebuild),
  // the number of the last collision before it was predicted, the number of its own last collision,
  // its mass and its list's centre. A prediction reads nothing of the partner's record: the event
  // checks, when it comes, that the partner's last collision is not a later one.
  struct alignas(64) Own {
    double time = infinity;
    std::uint64_t predicted_after = 0, last_collision = 0;
    std::uint32_t partner = none;
    std::uint32_t cell = 0;  ///< the cell its list's centre is filed in
    double mass = 1;
    Vector centre = Vector::Zero();
  };
  detail::Array<Own> own_;
  // What a rebuild reads of the balls around: each cell's slots, slots_ from c slots_ (head_[c] of them
  // taken), each a ball's list centre, its radius and its number, so that a rebuild reads the cells
  // around it in runs, not ball by ball.
  struct Slot {
    Vector centre = Vector::Zero();
    double radius = 0;
    std::uint32_t ball = 0;
  };
  detail::Array<Slot> slot_;
  std::size_t slots_ = 8;
  detail::Array<std::uint32_t> neighbour_;     ///< ball i's list: capacity_ entries from i capacity_
  std::size_t capacity_ = 0;
  // Kept between passes of reorder() and refile(), so that they touch no fresh memory.
  std::vector<std::uint32_t> order_, renumbered_;
  detail::Array<Ball> spare_ball_;
  detail::Array<Own> spare_own_;
  detail::Array<std::uint32_t> spare_identity_, spare_lists_;
  std::vector<Wraps> spare_wraps_;
  /// From here the balls lie beyond the caches and the look ahead pays.
  static constexpr std::size_t look_ahead_from = std::size_t{1} << 13;
};

// The longer members, defined out of the class body.

template <int D>
inline void ListGas<D>::check_no_overlap() const {
  for (std::size_t i = 0; i < ball_.size(); ++i) {
    const std::uint32_t* list = list_of(i);
    for (std::uint32_t k = 0; k < count_of(i); ++k) {
      const std::size_t j = list[k];
      if (j <= i) continue;
      const double contact = ball_[i].radius + ball_[j].radius;
      const double distance = nearest_image(ball_[i].position, ball_[j].position).norm();
      if (distance < contact * (1 - overlap_tolerance)) {
        const std::size_t a = std::min(identity_[i], identity_[j]), b = std::max(identity_[i], identity_[j]);
        std::ostringstream text;
        text << "balls " << a << " and " << b << " overlap: their centres are " << distance
             << " apart on their nearest images, expected at least the sum of their radii (" << contact << ")";
        throw std::invalid_argument(text.str());
      }
    }
  }
}

template <int D>
inline void ListGas<D>::reorder() {
  const std::size_t n = ball_.size();
  for (std::size_t i = 0; i < n; ++i) bring_to_now(i);
  std::vector<std::uint32_t>& order = order_;  // order[k]: the ball that becomes ball k
  order.clear();
  for (std::size_t c = 0; c < head_.size(); ++c) {
    for (std::uint32_t k = 0; k < head_[c]; ++k) order.push_back(slot_[c * slots_ + k].ball);
  }
  std::vector<std::uint32_t>& renumbered = renumbered_;  // the inverse: ball i becomes renumbered[i]
  renumbered.resize(n);
  for (std::size_t k = 0; k < n; ++k) renumbered[order[k]] = static_cast<std::uint32_t>(k);
  permute(ball_, spare_ball_, order);
  permute(own_, spare_own_, order);
  permute(identity_, spare_identity_, order);
  permute(wraps_, spare_wraps_, order);
  spare_lists_.resize(neighbour_.size());
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t* from = &neighbour_[order[k] * capacity_];
    std::uint32_t* to = &spare_lists_[k * capacity_];
    to[0] = from[0];
    for (std::uint32_t m = 1; m <= from[0]; ++m) to[m] = renumbered[from[m]];
  }
  neighbour_.swap(spare_lists_);
  for (Own& o : own_) {
    if (o.partner != none) o.partner = renumbered[o.partner];
  }
  for (std::size_t c = 0; c < head_.size(); ++c) {
    for (std::uint32_t k = 0; k < head_[c]; ++k) slot_[c * slots_ + k].ball = renumbered[slot_[c * slots_ + k].ball];
  }
  this->refile();
}

template <int D>
inline void ListGas<D>::find_neighbours(std::size_t i, bool later_only) {
  const Vector& centre = own_[i].centre;
  const double radius = ball_[i].radius;
  const auto take = [&](const Slot& slot, double squared_distance) {
    const double reach = shell_ * (radius + slot.radius);
    if (squared_distance < reach * reach && slot.ball != i && !(later_only && slot.ball < i)) {
      add_neighbour(i, slot.ball);
      add_neighbour(slot.ball, i);
    }
  };
  if (cells_per_side_ == 1) {
    for (std::uint32_t k = 0; k < head_[0]; ++k) take(slot_[k], nearest_image(centre, slot_[k].centre).squaredNorm());
    return;
  }
  // Along each axis the three cells' terms of cell_of and where ball i's centre lies as seen from
  // them: a cell wrapped around the box sees it a side away, so that a neighbour's distance needs no
  // nearest image (the box is at least three cells wide).
  std::size_t part[D][3];
  double origin[D][3];
  const Cell c = cell_coordinates(centre);
  for (int k = 0; k < D; ++k) {
    const std::uint32_t* offset = axis_offset_[k].data();
    const double x = centre[k];
    part[k][0] = offset[wrapped(c[k] - 1)];
    part[k][1] = offset[c[k]];
    part[k][2] = offset[wrapped(c[k] + 1)];
    origin[k][0] = c[k] == 0 ? x + side_ : x;
    origin[k][1] = x;
    origin[k][2] = c[k] == cells_per_side_ - 1 ? x - side_ : x;
  }
  const auto visit = [&](std::size_t cell, double o0, double o1, double o2) {
    for (std::uint32_t k = 0, count = head_[cell]; k < count; ++k) {
      const Slot& other = slot_[cell * slots_ + k];
      const double d0 = other.centre[0] - o0, d1 = other.centre[1] - o1;
      double squared = d0 * d0 + d1 * d1;
      if constexpr (D == 3) {
        const double d2 = other.centre[2] - o2;
        squared += d2 * d2;
      }
      take(other, squared);
    }
  };
  if constexpr (D == 2) {
    for (int b = 0; b < 3; ++b)
      for (int a = 0; a < 3; ++a) visit(part[1][b] + part[0][a], origin[0][a], origin[1][b], 0);
  } else {
    for (int cc = 0; cc < 3; ++cc)
      for (int b = 0; b < 3; ++b)
        for (int a = 0; a < 3; ++a)
          visit(part[2][cc] + part[1][b] + part[0][a], origin[0][a], origin[1][b], origin[2][cc]);
  }
}

template <int D>
inline void ListGas<D>::prefetch_next_events() {
  calendar_.look_ahead(3, [this](std::uint32_t k, int ahead) {
    if (ahead == 3) {
      detail::prefetch(&own_[k]);
      detail::prefetch(&ball_[k]);
      detail::prefetch(&neighbour_[k * capacity_]);
      return;
    }
    const std::uint32_t partner = own_[k].partner;
    if (ahead == 2) {
      prefetch_neighbours(k);
      if (partner == none) prefetch_rebuild(k);
      if (partner != none) {
        detail::prefetch(&own_[partner]);
        detail::prefetch(&ball_[partner]);
        detail::prefetch(&neighbour_[partner * capacity_]);
        calendar_.prefetch_record(partner);
      }
    } else if (partner != none) {
      prefetch_neighbours(partner);
    }
  });
}

}  // namespace billiards::simulation::detail
