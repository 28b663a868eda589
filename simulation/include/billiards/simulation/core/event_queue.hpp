/// \file
/// The engines' event queue: the earliest predicted event first. Two implementations behind the same
/// idea:
/// - EventHeap, a binary heap of predicted events (the table and the shot): O(log E) a push or a pop,
///   stale predictions dropped when they reach the top;
/// - EventCalendar (event_calendar.hpp), a calendar queue holding one next event per ball (the gas):
///   O(1) a step on average, for the 10^3 to 10^6 balls of a gas, where a heap's O(log N) and its
///   scattered memory cost more than the calendar's buckets.
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
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

}  // namespace billiards::simulation::detail
