/// \file
/// The engines' event queue: the earliest predicted event first. Three implementations behind the same
/// idea:
/// - EventHeap, a binary heap of predicted events (the table): O(log E) a push or a pop, stale
///   predictions dropped when they reach the top;
/// - OwnedEvents, a small heap of predicted events per ball and a scan of their earliest (the shot):
///   a ball's predictions, stale together once it changes, dropped at once, so that the heaps hold few
///   stale ones and stay shallow; the scan is O(N) a pop, as each event's predictions are;
/// - EventCalendar (event_calendar.hpp), a calendar queue holding one next event per ball (the gas):
///   O(1) a step on average, for the 10^3 to 10^6 balls of a gas, where a heap's O(log N) and its
///   scattered memory cost more than the calendar's buckets.
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <limits>
#include <vector>

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
/// small min-heap ordered by `Later`, the earliest of all found by a scan of the owners' earliest times
/// (kept in one array beside the heaps). `Later` must order by the events' `time` (a double) first and
/// break ties as it likes. clear() drops an owner's events at once; other stale events are the caller's
/// to skip, as with EventHeap.
template <class Event, class Later = std::greater<>>
class OwnedEvents {
 public:
  /// A queue for owners 0 … owners − 1.
  explicit OwnedEvents(std::size_t owners = 0)
      : heaps_(owners), times_(owners, std::numeric_limits<double>::infinity()) {}
  /// Whether no event is queued.
  [[nodiscard]] bool empty() const noexcept { return size_ == 0; }
  /// How many events are queued, stale ones included.
  [[nodiscard]] std::size_t size() const noexcept { return size_; }
  /// The owner of the earliest event (the queue must not be empty): the least of the owners' earliest
  /// times, read from one array; owners whose earliest events share that time compared in full.
  [[nodiscard]] std::size_t earliest() const {
    double least = std::numeric_limits<double>::infinity();
    for (const double t : times_) least = std::min(least, t);
    std::size_t best = heaps_.size();
    for (std::size_t k = 0; k < heaps_.size(); ++k) {
      if (times_[k] == least && !heaps_[k].empty() &&
          (best == heaps_.size() || Later{}(heaps_[best].front(), heaps_[k].front())))
        best = k;
    }
    return best;
  }
  /// The earliest event of `owner` (which must have one).
  [[nodiscard]] const Event& top(std::size_t owner) const { return heaps_[owner].front(); }
  /// Queues `event` as `owner`'s.
  void push(std::size_t owner, const Event& event) {
    std::vector<Event>& heap = heaps_[owner];
    heap.push_back(event);
    std::push_heap(heap.begin(), heap.end(), Later{});
    times_[owner] = heap.front().time;
    ++size_;
  }
  /// Takes `owner`'s earliest event out and returns it (`owner` must have one).
  Event pop(std::size_t owner) {
    std::vector<Event>& heap = heaps_[owner];
    std::pop_heap(heap.begin(), heap.end(), Later{});
    Event event = heap.back();
    heap.pop_back();
    times_[owner] = heap.empty() ? std::numeric_limits<double>::infinity() : heap.front().time;
    --size_;
    return event;
  }
  /// Drops every event of `owner`.
  void clear(std::size_t owner) noexcept {
    size_ -= heaps_[owner].size();
    heaps_[owner].clear();
    times_[owner] = std::numeric_limits<double>::infinity();
  }

 private:
  std::vector<std::vector<Event>> heaps_;
  std::vector<double> times_;  // each owner's earliest event's time, +∞ for none
  std::size_t size_ = 0;
};

}  // namespace billiards::simulation::detail
