/// \file
/// The engines' event queue: the earliest predicted event first. Three implementations behind the same
/// idea:
/// - EventHeap, a binary heap of predicted events (the table): O(log E) a push or a pop, stale
///   predictions dropped when they reach the top;
/// - OwnedEvents, a short run of predicted events per ball, its earliest first, and a scan of the
///   balls' earliest (the shot): a ball's predictions, stale together once it changes, dropped at once,
///   so that the runs hold few stale ones and stay short; a pop scans its ball's run and the balls'
///   earliest, O(N), as each event's predictions are;
/// - EventCalendar (event_calendar.hpp), a calendar queue holding one next event per ball (the gas):
///   O(1) a step on average, for the 10^3 to 10^6 balls of a gas, where a heap's O(log N) and its
///   scattered memory cost more than the calendar's buckets.
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace billiards::simulation::detail {

/// A min-heap of predicted events ordered by `Later` (std::greater<>: an Event with operator> on its
/// time and whatever breaks ties). Stale events are the caller's to skip: pop() returns whatever is
/// earliest.
template <class Event, class Later = std::greater<>>
class EventHeap {
 public:
  /// Whether no event is queued.
  [[nodiscard]] bool empty() const noexcept { return heap_.empty(); }
  /// How many events are queued, stale ones included.
  [[nodiscard]] std::size_t size() const noexcept { return heap_.size(); }
  /// The earliest event (the queue must not be empty).
  [[nodiscard]] const Event& top() const { return heap_.front(); }
  /// Queues `event`.
  void push(const Event& event) {
    heap_.push_back(event);
    std::push_heap(heap_.begin(), heap_.end(), Later{});
  }
  /// Takes the earliest event out and returns it (the queue must not be empty).
  Event pop() {
    std::pop_heap(heap_.begin(), heap_.end(), Later{});
    Event event = heap_.back();
    heap_.pop_back();
    return event;
  }
  /// Calls `change(Event&)` on every queued event; `change` must keep their order (the table shifts
  /// every time by the same amount).
  template <class Change>
  void change_all(Change&& change) {
    for (Event& event : heap_) change(event);
  }

 private:
  std::vector<Event> heap_;
};

/// Predicted events kept by owner (a ball: its own events and the pairs it predicted), each owner's in a
/// short run whose first is its earliest by `Later` and the rest in no order (a push compares with the
/// first; a pop scans the rest for the next: an owner holds a few events, for which a heap's sifting of
/// whole events costs more than the scan), the earliest of all found by a scan of the owners' earliest
/// times (kept in one array beside the runs). `Later` must order by the events' `time` (a double) first
/// and break ties as it likes; events equal under it come out in an unspecified order. clear() drops an
/// owner's events at once; other stale events are the caller's to skip, as with EventHeap. The runs
/// share one array, of equal room for each owner, that doubles every owner's room when one's is full.
template <class Event, class Later = std::greater<>>
class OwnedEvents {
 public:
  /// A queue for owners 0 … owners − 1, with room for `room` events each before its array grows.
  explicit OwnedEvents(std::size_t owners = 0, std::size_t room = 16)
      : room_(std::max<std::size_t>(room, 1)),
        events_(owners * room_),
        sizes_(owners, 0),
        times_((owners + 1) / 2 * 2, std::numeric_limits<double>::infinity()) {}
  /// Whether no event is queued.
  [[nodiscard]] bool empty() const noexcept { return size_ == 0; }
  /// How many events are queued, stale ones included.
  [[nodiscard]] std::size_t size() const noexcept { return size_; }
  /// The owner of the earliest event (the queue must not be empty): the least of the owners' earliest
  /// times, read from one array; owners whose earliest events share that time compared in full.
  [[nodiscard]] std::size_t earliest() const {
#if defined(__SSE2__)
    // Up to 64 owners, two at a time: the least time, then a bit for each owner at it; where that is
    // one owner (the rule: ties are rare), it is the answer, found without a branch on the times.
    if (times_.size() <= 64) {
      const double least = least_time();
      const std::uint64_t at_least = owners_at(least);
      if (least < std::numeric_limits<double>::infinity() && at_least != 0 &&
          (at_least & (at_least - 1)) == 0)
        return static_cast<std::size_t>(std::countr_zero(at_least));
    }
#endif
    double least = std::numeric_limits<double>::infinity();
    for (const double t : times_) least = std::min(least, t);
    const std::size_t owners = sizes_.size();
    std::size_t best = owners;
    for (std::size_t k = 0; k < owners; ++k) {
      if (times_[k] == least && sizes_[k] != 0 && (best == owners || Later{}(top(best), top(k)))) best = k;
    }
    return best;
  }
  /// The earliest event of `owner` (which must have one).
  [[nodiscard]] const Event& top(std::size_t owner) const { return events_[owner * room_]; }
  /// Queues `event` as `owner`'s.
  [[gnu::always_inline]] inline void push(std::size_t owner, const Event& event) {
    if (sizes_[owner] == room_) widen();
    Event* run = events_.data() + owner * room_;
    const std::size_t n = sizes_[owner]++;
    // Compared and stored from `event` itself, never read back from where it was just written.
    if (n == 0 || Later{}(run[0], event)) {
      if (n != 0) run[n] = run[0];
      run[0] = event;
      times_[owner] = event.time;
    } else {
      run[n] = event;
    }
    ++size_;
  }
  /// Takes `owner`'s earliest event out and returns it (`owner` must have one).
  Event pop(std::size_t owner) {
    Event* run = events_.data() + owner * room_;
    const Event event = run[0];
    const std::size_t n = --sizes_[owner];
    if (n == 0) {
      times_[owner] = std::numeric_limits<double>::infinity();
    } else {
      std::size_t best = 1;
      for (std::size_t k = 2; k <= n; ++k) {
        if (Later{}(run[best], run[k])) best = k;
      }
      run[0] = run[best];
      run[best] = run[n];
      times_[owner] = run[0].time;
    }
    --size_;
    return event;
  }
  /// Drops every event of `owner`.
  void clear(std::size_t owner) noexcept {
    size_ -= sizes_[owner];
    sizes_[owner] = 0;
    times_[owner] = std::numeric_limits<double>::infinity();
  }

 private:
  // Every owner's room doubled, its run kept as it is.
  void widen() {
    std::vector<Event> wider(2 * events_.size());
    for (std::size_t k = 0; k < sizes_.size(); ++k)
      std::copy_n(events_.begin() + static_cast<std::ptrdiff_t>(k * room_), sizes_[k],
                  wider.begin() + static_cast<std::ptrdiff_t>(2 * k * room_));
    events_.swap(wider);
    room_ *= 2;
  }
#if defined(__SSE2__)
  // The least of times_, in two chains of pairs.
  [[nodiscard]] double least_time() const {
    const double* t = times_.data();
    __m128d low = _mm_set1_pd(std::numeric_limits<double>::infinity()), other = low;
    std::size_t k = 0;
    for (; k + 4 <= times_.size(); k += 4) {
      low = _mm_min_pd(low, _mm_loadu_pd(t + k));
      other = _mm_min_pd(other, _mm_loadu_pd(t + k + 2));
    }
    if (k < times_.size()) low = _mm_min_pd(low, _mm_loadu_pd(t + k));
    low = _mm_min_pd(low, other);
    return std::min(_mm_cvtsd_f64(low), _mm_cvtsd_f64(_mm_unpackhi_pd(low, low)));
  }
  // A bit for each entry of times_ (at most 64) equal to `time`.
  [[nodiscard]] std::uint64_t owners_at(double time) const {
    const double* t = times_.data();
    const __m128d at = _mm_set1_pd(time);
    std::uint64_t bits = 0;
    for (std::size_t k = 0; k < times_.size(); k += 2)
      bits |= static_cast<std::uint64_t>(_mm_movemask_pd(_mm_cmpeq_pd(_mm_loadu_pd(t + k), at))) << k;
    return bits;
  }
#endif
  std::size_t room_;                // each owner's run in events_
  std::vector<Event> events_;       // owner k's run at k room_, its first sizes_[k]
  std::vector<std::size_t> sizes_;  // each owner's count of events
  std::vector<double> times_;       // each owner's earliest event's time, +∞ for none (and a pair's pad)
  std::size_t size_ = 0;
};

}  // namespace billiards::simulation::detail
