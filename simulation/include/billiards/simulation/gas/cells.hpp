// The gas's cell engine, for equal balls: the box cut into cells at least a diameter wide, each
// ball's next event the earlier of its next cell crossing and its earliest collision with a ball of
// the 3^D cells around it. Used by Gas (gas.hpp), which documents the choice between engines.
#pragma once

#include <billiards/simulation/gas/engine.hpp>
#include <billiards/simulation/core/large_array.hpp>
#include <billiards/simulation/core/prefetch.hpp>

#include <billiards/collision.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace billiards::simulation::detail {

template <int D>
class CellGas : public GasEngine<D, CellGas<D>> {
  using Base = GasEngine<D, CellGas<D>>;
  friend Base;

 public:
  using typename Base::Vector;
  using Base::nearest_image;
  static constexpr bool lists = false;

  // Equal balls only (the caller checks).
  CellGas(const GasSetup<D>& setup, std::uint64_t max_events_without_collision)
      : Base(setup, max_events_without_collision), diameter_(2 * setup.radius) {
    const std::size_t n = setup.balls.size();
    // Cells at least one diameter wide.
    this->lay_out_cells(gas::grid_cells_per_side(D, n, side_ / diameter_));
    ball_.resize(n);
    own_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      ball_[i].position = setup.balls[i].position;
      ball_[i].velocity = setup.balls[i].velocity;
      for (int k = 0; k < D; ++k) ball_[i].position[k] = this->into_box(ball_[i].position[k]);
      own_[i].coordinates = this->cell_coordinates(ball_[i].position);
      own_[i].cell = static_cast<std::uint32_t>(this->cell_index(own_[i].coordinates));
      insert(i);
    }
    check_no_overlap();
    for (std::size_t i = 0; i < n; ++i) predict_in_full(i);
    calendar_.defer_filings(n >= look_ahead_from);
    this->refile();
    this->reset_measurements();
  }

  // What the base reads of ball i.
  const Vector& velocity(std::size_t i) const { return ball_[i].velocity; }
  double mass_of(std::size_t) const { return this->mass_; }
  double radius_of(std::size_t) const { return this->radius_; }
  Vector position_now(std::size_t i) const { return ball_[i].position + ball_[i].velocity * (now_ - ball_[i].updated); }
  double event_time(std::size_t i) const { return own_[i].event_time(); }

 private:
  using typename Base::Cell;
  using Base::none;
  using Base::infinity;
  using Base::side_;
  using Base::now_;
  using Base::cells_per_side_;
  using Base::cell_width_;
  using Base::axis_offset_;
  using Base::head_;
  using Base::identity_;
  using Base::wraps_;
  using Base::calendar_;
  using Base::collision_number_;
  using Base::since_refile_;
  using Base::wrapped;
  // The cells a prediction searches and their lists' first balls, asked of memory by gather() for the
  // search() that follows.
  struct Gathered {
    std::uint32_t first[D == 2 ? 9 : 27];
    int cells = 0;
  };

  // No two balls closer than a diameter (less 1e-9 of one) on their nearest images: each ball against
  // the balls of the 3^D cells around its own, which hold every ball within a diameter of it.
  void check_no_overlap() const;

  void insert(std::size_t i) {
    const std::size_t c = own_[i].cell;
    ball_[i].previous = none;
    ball_[i].next = head_[c];
    if (head_[c] != none) ball_[head_[c]].previous = static_cast<std::uint32_t>(i);
    head_[c] = static_cast<std::uint32_t>(i);
  }
  void remove(std::size_t i) {
    if (ball_[i].previous != none)
      ball_[ball_[i].previous].next = ball_[i].next;
    else
      head_[own_[i].cell] = ball_[i].next;
    if (ball_[i].next != none) ball_[ball_[i].next].previous = ball_[i].previous;
  }

  void bring_to_now(std::size_t i) {
    ball_[i].position += ball_[i].velocity * (now_ - ball_[i].updated);
    ball_[i].updated = now_;
  }

  // Ball i's next event, predicted in full, and its place in the calendar.
  void predict(std::size_t i) {
    predict_in_full(i);
    calendar_.update(static_cast<std::uint32_t>(i), own_[i].event_time());
  }

  // Beyond the caches: asks memory for what filing ball i at its event time will read, so that the
  // calendar's miss overlaps the work before the filing instead of following it.
  void prefetch_filing(std::size_t i) {
    if (ball_.size() >= look_ahead_from)
      calendar_.prefetch_update(static_cast<std::uint32_t>(i), own_[i].event_time());
  }

  // Ball i's next crossing and its earliest collision with a ball of the 3^D cells around it, any
  // candidate it had forgotten; `gathered`, where given, holds the 3^D cells around it, gathered earlier.
  void predict_in_full(std::size_t i, const Gathered* gathered = nullptr) {
    predict_crossing(i);
    own_[i].collision_time = infinity;
    own_[i].partner = none;
    if (gathered != nullptr)
      search(i, *gathered);
    else
      predict_collisions(i, all_axes, 0);
  }

  // After ball i crossed into a new cell along `axis` by `step`: its next crossing, and collisions with
  // the balls of the cells that have just come around it (3^(D−1), not 3^D: the rest were around it
  // before). The earliest collision found before stays a candidate: its pair was predicted on the
  // same paths, and a pair first around it now lies in the new cells. (A ball of the new cells that
  // predicted ball i on its own paths since keeps that event itself.)
  // `gathered`, where given, holds those cells, gathered earlier.
  void predict_after_crossing(std::size_t i, int axis, int step, const Gathered* gathered = nullptr) {
    predict_crossing(i);
    prefetch_filing(i);  // its time, unless the new cells hold an earlier collision
    if (gathered != nullptr)
      search(i, *gathered);
    else
      predict_collisions(i, axis, step);
    calendar_.update(static_cast<std::uint32_t>(i), own_[i].event_time());
  }

  // Ball i's next cell crossing: the earliest time it reaches a face of its cell.
  void predict_crossing(std::size_t i) {
    bring_to_now(i);
    Own& own = own_[i];
    own.crossing_time = infinity;
    for (int k = 0; k < D; ++k) {
      const double v = ball_[i].velocity[k];
      if (v == 0) continue;
      const double bound = (own.coordinates[k] + (v > 0 ? 1 : 0)) * cell_width_;
      const double t = now_ + std::max(0.0, (bound - ball_[i].position[k]) / v);
      if (t < own.crossing_time) {
        own.crossing_time = t;
        own.axis = static_cast<std::int8_t>(k);
        own.step = static_cast<std::int8_t>(v > 0 ? 1 : -1);
      }
    }
  }

  static constexpr int all_axes = -1;

  // Ball i's earliest collision with a ball of the cells around its own (every one of the 3^D when
  // `axis` is all_axes, else those one step beyond it along `axis`), kept where earlier than the
  // candidate it has. Ball i is at now.
  void predict_collisions(std::size_t i, int axis, int step) {
    Gathered gathered;
    gather(own_[i].coordinates, axis, step, gathered);
    search(i, gathered);
  }

  // The cells around `centre` (every one of the 3^D when `axis` is all_axes, else those one step beyond
  // it along `axis`) and their lists' first balls. The cells, their heads and their first balls are
  // asked of memory all at once before any is read: beyond the caches the misses then overlap instead
  // of following one another.
  void gather(const Cell& centre, int axis, int step, Gathered& gathered) const;

  // Ball i's earliest collision with a ball of the gathered cells, kept where earlier than the candidate
  // it has. Ball i is at now; the cells' lists are as they were gathered.
  void search(std::size_t i, const Gathered& gathered) {
    const std::uint32_t* first = gathered.first;
    const int cells = gathered.cells;
    Own& own = own_[i];
    const double before = own.collision_time;
    for (int n = 0; n < cells; ++n) {
      for (std::uint32_t j = first[n]; j != none; j = ball_[j].next) {
        if (j == i) continue;
        const Vector other = ball_[j].position + ball_[j].velocity * (now_ - ball_[j].updated);
        const Vector p = nearest_image(ball_[i].position, other);
        // A pair moving apart never meets (time_of_impact would say +∞): skip the call.
        if (p.dot(ball_[j].velocity - ball_[i].velocity) >= 0) continue;
        const double t = billiards::time_of_impact(Vector::Zero().eval(), ball_[i].velocity, p,
                                                   ball_[j].velocity, diameter_);
        if (now_ + t < own.collision_time) {
          own.collision_time = now_ + t;
          own.partner = j;
        }
      }
    }
    if (own.collision_time < before) own.predicted_after = collision_number_;
  }

  // Asks memory for what the next events will read, so that their misses overlap this event's work
  // instead of following it (the calendar's look ahead): the records of the balls two buckets ahead,
  // and for those one bucket ahead, whose records were asked for before, their partners' records and
  // (2-D) the list heads of the cells their predictions will search and, for a crossing, the records
  // its removal from its cell's list writes.
  void prefetch_next_events();

  // Asks memory for the list heads of a block of cells, low[a] to high[a] along each axis (at most five
  // cells, wrapped around the box): those of its 2^D corners, which lie in every tile the block meets
  // (a tile is four cells wide). In 2-D a tile's heads fill one cache line, so these are all the
  // block's lines. (In 3-D a tile's take four, and asking for the heads of the cells around the next
  // events measured no faster: 10^6 spheres 1–3 % slower; in 2-D, 10^6 disks 12 % faster.)
  void prefetch_heads(const int (&low)[D], const int (&high)[D]) {
    for (int corner = 0; corner < (1 << D); ++corner) {
      std::size_t index = 0;
      for (int a = 0; a < D; ++a)
        index += axis_offset_[a][wrapped((corner >> a & 1) != 0 ? high[a] : low[a])];
      detail::prefetch(&head_[index]);
    }
  }

  // Renumbers the balls in the order of their cells, so that balls near in space are near in memory
  // (a gas mixes them, and beyond the caches every prediction would otherwise miss them). Nothing
  // physical changes: every ball is brought to now on its own line, and the events keep their times,
  // with partners renumbered, filed anew in the calendar.
  //
  // The records move in place, one cycle of the renumbering at a time, and the pass's index arrays are
  // kept from one pass to the next: no fresh memory, whose first touch costs a page fault a page (at
  // 10^6 disks a pass that copied the records into new arrays took about 0.6 s, most of it faults;
  // in place, about 0.1 s).
  void reorder();

  // Runs events until `collisions` more collisions or until the next event lies beyond `until`, calling
  // `on_collision` after each collision; returns the collisions run (GasEngine::run_events picks
  // `beyond_caches`). Beyond the caches, each event gathers the cells its predictions will search at its
  // start, before the work that needs none of them (a crossing's move between lists, a collision's
  // resolution and the first ball's search), so that their misses overlap that work; a crossing's new
  // cells do not include the two whose lists its move changes (the box is at least three cells wide), and
  // a collision changes no list. The same events bit for bit. 10^6 disks 17 % more collisions a second
  // (9 % of it the flattening), 10^6 spheres 10 %, 10^5 disks 13 %, 1024 balls even (alternating
  // separate processes on one core).
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
      if (own.event_time() > until) break;
      if constexpr (beyond_caches) prefetch_next_events();
      now_ = own.event_time();
      if (own.crossing_first()) {  // a cell crossing
        Gathered gathered;
        if constexpr (beyond_caches) {
          Cell next = own.coordinates;
          next[own.axis] = static_cast<int>(wrapped(next[own.axis] + own.step));
          gather(next, own.axis, own.step, gathered);
        }
        bring_to_now(i);
        remove(i);
        const int axis = own.axis, step = own.step;
        int& c = own.coordinates[axis];
        c += step;
        if (c == cells_per_side_) c = 0, ball_[i].position[axis] -= side_, ++wraps_[i][axis];
        if (c < 0) c = cells_per_side_ - 1, ball_[i].position[axis] += side_, --wraps_[i][axis];
        own.cell = static_cast<std::uint32_t>(this->cell_index(own.coordinates));
        insert(i);
        ++this->own_events_;
        predict_after_crossing(i, axis, step, beyond_caches ? &gathered : nullptr);
      } else if (own_[own.partner].last_collision > own.predicted_after) {
        predict(i);  // stale: the partner has collided since
      } else {
        const std::size_t j = own.partner;
        Gathered around_i, around_j;
        if constexpr (beyond_caches) {
          gather(own_[i].coordinates, all_axes, 0, around_i);
          gather(own_[j].coordinates, all_axes, 0, around_j);
        }
        // The partner leaves its place in the calendar's lists: asked of memory now, written below.
        if constexpr (beyond_caches) calendar_.prefetch_removal(static_cast<std::uint32_t>(j));
        bring_to_now(i);
        bring_to_now(j);
        const Vector image = ball_[i].position + nearest_image(ball_[i].position, ball_[j].position);
        this->measure_contact((image - ball_[i].position).norm(), diameter_);
        const auto [vi, vj] = billiards::collide_if_approaching(1.0, ball_[i].position, ball_[i].velocity,
                                                                1.0, image, ball_[j].velocity);
        const Vector impulse = vi - ball_[i].velocity;
        const bool changed = !(vi.array() == ball_[i].velocity.array()).all();
        ball_[i].velocity = vi;
        ball_[j].velocity = vj;
        own_[i].last_collision = own_[j].last_collision = ++collision_number_;
        // Both predicted before either is filed, each filing asked of memory ahead of it: the
        // calendar's misses overlap the other ball's prediction (10^6 balls: 6–9 % more collisions a
        // second with the prefetches above and in the look ahead).
        predict_in_full(i, beyond_caches ? &around_i : nullptr);
        prefetch_filing(i);
        predict_in_full(j, beyond_caches ? &around_j : nullptr);
        prefetch_filing(j);
        calendar_.update(static_cast<std::uint32_t>(i), own_[i].event_time());
        calendar_.update(static_cast<std::uint32_t>(j), own_[j].event_time());
        if (changed) {
          this->count_collision(ball_[i].position - image, impulse, this->mass_, this->mass_, diameter_);
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

  double diameter_ = 1;
  // What a prediction reads of each neighbour, in one place, one cache line (a disk's record is 64 bytes
  // without the alignment too: Eigen aligns a 2-vector to 16 bytes, so its velocity starts at byte 32):
  // its position at its last update, that time, its velocity, and its links in its cell's list.
  struct alignas(64) Ball {
    Vector position = Vector::Zero();
    double updated = 0;
    Vector velocity = Vector::Zero();
    std::uint32_t next = none, previous = none;
  };
  detail::Array<Ball> ball_;
  // What an event reads of its own ball, in one place (one cache line): its next crossing, its earliest
  // predicted collision (the partner, and the number of the last collision before it was predicted),
  // its cell, the number of its own last collision. Its next event is the earlier of the two (the
  // crossing where they tie). A prediction reads nothing of the partner's record: the event checks, when
  // it comes, that the partner's last collision is not a later one.
  struct alignas(64) Own {
    double crossing_time = infinity, collision_time = infinity;
    std::uint64_t predicted_after = 0, last_collision = 0;
    std::uint32_t partner = none;
    std::uint32_t cell = 0;
    Cell coordinates = Cell::Zero();
    std::int8_t axis = 0, step = 0;  ///< the crossing: along which axis, +1 or −1
    double event_time() const { return std::min(crossing_time, collision_time); }
    bool crossing_first() const { return !(collision_time < crossing_time); }
  };
  detail::Array<Own> own_;
  // Kept between passes of reorder() and refile(), so that they touch no fresh memory.
  std::vector<std::uint32_t> order_, renumbered_;
  std::vector<bool> placed_;
  /// From here the balls lie beyond the caches and the look ahead pays (10^4 disks: 2 % slower with it,
  /// 10^5: 12–16 % faster; at 1024 it costs 10 %).
  static constexpr std::size_t look_ahead_from = std::size_t{1} << 15;
};

// The longer members, defined out of the class body.

template <int D>
inline void CellGas<D>::check_no_overlap() const {
  const double closest = diameter_ * (1 - overlap_tolerance);
  for (std::size_t i = 0; i < ball_.size(); ++i) {
    Gathered around;
    gather(own_[i].coordinates, all_axes, 0, around);
    for (int n = 0; n < around.cells; ++n) {
      for (std::uint32_t j = around.first[n]; j != none; j = ball_[j].next) {
        if (j <= i) continue;
        const double distance = nearest_image(ball_[i].position, ball_[j].position).norm();
        if (distance < closest) {
          std::ostringstream text;
          text << "balls " << i << " and " << j << " overlap: their centres are " << distance
               << " apart on their nearest images, expected at least a diameter (" << diameter_ << ")";
          throw std::invalid_argument(text.str());
        }
      }
    }
  }
}

template <int D>
inline void CellGas<D>::reorder() {
  const std::size_t n = ball_.size();
  for (std::size_t i = 0; i < n; ++i) bring_to_now(i);
  std::vector<std::uint32_t>& order = order_;  // order[k]: the ball that becomes ball k
  order.clear();
  for (std::size_t c = 0; c < head_.size(); ++c) {
    for (std::uint32_t i = head_[c]; i != none; i = ball_[i].next) order.push_back(i);
  }
  std::vector<std::uint32_t>& renumbered = renumbered_;  // the inverse: ball i becomes renumbered[i]
  renumbered.resize(n);
  for (std::size_t k = 0; k < n; ++k) renumbered[order[k]] = static_cast<std::uint32_t>(k);
  // Each cycle k → order[k] → order[order[k]] … : place k takes the records of place order[k], which
  // the cycle has not yet overwritten, and the cycle's last place the first place's, kept aside.
  placed_.assign(n, false);
  for (std::size_t start = 0; start < n; ++start) {
    if (placed_[start]) continue;
    const Ball first_ball = ball_[start];
    const Own first_own = own_[start];
    const std::uint32_t first_identity = identity_[start];
    const typename Base::Wraps first_wraps = wraps_[start];
    for (std::size_t k = start;;) {
      placed_[k] = true;
      const std::size_t from = order[k];
      if (from == start) {
        ball_[k] = first_ball;
        own_[k] = first_own;
        identity_[k] = first_identity;
        wraps_[k] = first_wraps;
        break;
      }
      ball_[k] = ball_[from];
      own_[k] = own_[from];
      identity_[k] = identity_[from];
      wraps_[k] = wraps_[from];
      k = from;
    }
  }
  for (Own& o : own_) {
    if (o.partner != none) o.partner = renumbered[o.partner];
  }
  std::fill(head_.begin(), head_.end(), none);
  for (std::size_t k = n; k-- > 0;) insert(k);
  this->refile();
}

template <int D>
inline void CellGas<D>::gather(const Cell& centre, int axis, int step, Gathered& gathered) const {
  constexpr int around = D == 2 ? 9 : 27;
  std::uint32_t* first = gathered.first;
  int cells = 0;
  {
    // Along each axis the cell coordinates to search, wrapped around the box, as the axis's terms
    // of cell_index: three (one step either side and the ball's own), or the one beyond.
    std::size_t part[D][3];
    int count[D];
    for (int k = 0; k < D; ++k) {
      const int c = centre[k];
      const std::uint32_t* offset = axis_offset_[k].data();
      if (k == axis) {
        part[k][0] = offset[wrapped(c + step)];
        count[k] = 1;
      } else {
        part[k][0] = offset[wrapped(c - 1)];
        part[k][1] = offset[c];
        part[k][2] = offset[wrapped(c + 1)];
        count[k] = 3;
      }
    }
    std::size_t cell[around];
    const auto add = [&](std::size_t index) {
      detail::prefetch(&head_[index]);
      cell[cells++] = index;
    };
    // The first axis fastest (cell_index's order within a tile; where ties between equal times are
    // broken, always the same way).
    if constexpr (D == 2) {
      for (int b = 0; b < count[1]; ++b)
        for (int a = 0; a < count[0]; ++a) add(part[1][b] + part[0][a]);
    } else {
      for (int c = 0; c < count[2]; ++c)
        for (int b = 0; b < count[1]; ++b)
          for (int a = 0; a < count[0]; ++a) add(part[2][c] + part[1][b] + part[0][a]);
    }
    for (int n = 0; n < cells; ++n) {
      first[n] = head_[cell[n]];
      if (first[n] != none) detail::prefetch(&ball_[first[n]]);
    }
  }
  gathered.cells = cells;
}

template <int D>
inline void CellGas<D>::prefetch_next_events() {
  calendar_.look_ahead(2, [this](std::uint32_t k, int ahead) {
    if (ahead > 1) {
      detail::prefetch(&own_[k]);
      detail::prefetch(&ball_[k]);
    } else if (const Own& own = own_[k]; !own.crossing_first()) {
      detail::prefetch(&own_[own.partner]);
      detail::prefetch(&ball_[own.partner]);
      calendar_.prefetch_record(own.partner);
      if constexpr (D == 2) {  // the 5 × 5 cells around ball k hold both balls' neighbourhoods
        const int low[D] = {own.coordinates[0] - 2, own.coordinates[1] - 2};
        const int high[D] = {own.coordinates[0] + 2, own.coordinates[1] + 2};
        prefetch_heads(low, high);
      }
    } else if constexpr (D == 2) {  // a crossing (in 3-D neither prefetch below measured faster)
      const Ball& ball = ball_[k];  // its neighbours in its cell's list, which its removal writes
      if (ball.previous != none) detail::prefetch(&ball_[ball.previous]);
      if (ball.next != none) detail::prefetch(&ball_[ball.next]);
      int low[D] = {own.coordinates[0] - 1, own.coordinates[1] - 1};  // the cells that come around it
      int high[D] = {own.coordinates[0] + 1, own.coordinates[1] + 1};
      low[own.axis] = high[own.axis] = own.coordinates[own.axis] + 2 * own.step;
      prefetch_heads(low, high);
    }
  });
}

}  // namespace billiards::simulation::detail
