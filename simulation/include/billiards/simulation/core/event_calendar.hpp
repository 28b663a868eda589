// The calendar of an event-driven simulation's next events: one pending time per item (a ball), the
// earliest found in O(1) on average whatever the number of items — a calendar queue (R. Brown, CACM
// 31 (1988) 1220), in the bounded form event-driven molecular dynamics uses (G. Paul, J. Comput. Phys.
// 221 (2007) 615; DynamO's "bounded priority queue").
//
// Time is cut into buckets of one width. A year of B buckets (B a power of two, at least the number of
// items) is a ring of doubly linked lists, one per bucket; a time beyond the year waits in
// an overflow list and enters the ring when its year comes. The bucket at the front is moved into a
// small binary heap (it may hold many equal times: a lattice's first events), whose top is the
// earliest time. Moving an item touches two short lists: no sift through log N levels of one big
// heap, most of them beyond the caches.
//
// Beyond the caches a filing into a later bucket may wait a few updates, its bucket's head asked of
// memory meanwhile (defer_filings).
//
// The width is chosen from the pending times themselves (reset): twice their mean spacing over the
// nearer half, so that a bucket holds a few items when the front reaches it and few times fall beyond
// the year. Any width gives the right order; the width decides only the speed.
#pragma once

#include <billiards/simulation/core/large_array.hpp>
#include <billiards/simulation/core/prefetch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

namespace billiards::simulation {

/// The calendar of an event-driven simulation's next events: one pending time per item (a ball), the
/// earliest found in O(1) on average whatever the number of items (a calendar queue; see the file).
class EventCalendar {
 public:
  /// No item: what earliest() returns when no item has a finite time.
  static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

  /// Files item i at times[i] for every i, with the width chosen from times − now. Every time must be
  /// ≥ now, or +∞ (an item with no event); none may be NaN.
  void reset(const std::vector<double>& times, double now) {
    if (times.size() > (std::size_t{1} << 31)) throw std::length_error("EventCalendar: more than 2^31 items");
    std::size_t buckets = 256;
    while (buckets < times.size()) buckets *= 2;
    mask_ = buckets - 1;
    head_.assign(buckets, none);
    item_.assign(times.size(), Item{});
    front_.clear();
    overflow_ = none;
    in_ring_ = 0;
    // The width: the mean spacing of the nearer half of the pending times (the median distance from
    // now over half the count). A median, not the nearest few, which may sit within rounding of now
    // (a lattice's balls on the cells' faces) and would make the year far too short.
    std::vector<double>& ahead = ahead_;  // kept from one reset to the next: no fresh memory to fault in
    ahead.clear();
    for (double t : times) {
      if (std::isnan(t) || t < now) throw std::invalid_argument("EventCalendar: a time is NaN or before now");
      if (std::isfinite(t) && t > now) ahead.push_back(t - now);  // times at now say nothing of a spacing
    }
    width_ = 0;
    if (!ahead.empty()) {
      const std::size_t k = (ahead.size() + 1) / 2;
      std::nth_element(ahead.begin(), ahead.begin() + static_cast<std::ptrdiff_t>(k - 1), ahead.end());
      width_ = spacings_a_bucket * ahead[k - 1] / static_cast<double>(k);
    }
    // The width must resolve now: bucket numbers below 2^52 stay exact integers in a double.
    width_ = std::max(width_, std::fabs(now) * 0x1p-50);
    if (!(width_ > 0) || !std::isfinite(width_)) width_ = 1;
    year_ = current_ = bucket_number(now);
    looked_ahead_from_ = std::numeric_limits<std::int64_t>::min();
    waiting_count_ = 0;
    for (std::size_t i = 0; i < times.size(); ++i) file(static_cast<std::uint32_t>(i), times[i]);
  }

  /// Whether update() defers a filing into a later bucket (off at first): the item then waits in a short
  /// queue, its bucket's list head asked of memory, and is filed a few updates later, or before the
  /// front moves on (a later bucket's time cannot be the earliest while the front holds any). The head's
  /// miss then overlaps the work in between instead of stalling the update: for items beyond the
  /// caches. Nothing observable changes: the earliest item, time() and the look ahead are the same.
  void defer_filings(bool on) {
    while (waiting_count_ > 0) file_waiting();
    defer_ = on;
  }

  /// Item i's pending time.
  double time(std::uint32_t i) const { return item_[i].time; }

  /// Moves item i to `time` (≥ the last earliest time returned, or +∞).
  void update(std::uint32_t i, double time) {
    unfile(i);
    if (defer_) {
      if (const std::optional<std::int64_t> b = bucket_this_year(time); b && *b > current_) {
        Item& item = item_[i];
        item.time = time;
        ++item.version;
        item.bucket = waiting;
        detail::prefetch(&head_[bucket_index(*b)]);
        if (waiting_count_ == waiting_size) file_waiting();
        waiting_[(waiting_first_ + waiting_count_++) % waiting_size] = i;
        return;
      }
    }
    file(i, time);
  }

  /// A look ahead at the events that come next, for prefetching: once the front has moved to a new
  /// bucket, calls `soon(item, ahead)` for each item of the `buckets` buckets after it (`ahead` 1 for
  /// the next, 2 for the one after, …), and asks memory for the calendar's records of the first two
  /// items of the bucket after those: the first's a call ahead, the second's from the first's record
  /// (a list is walked one record a call, so that the walk never waits on memory; a bucket holds two
  /// items on average). A hint, never an order: an item filed meanwhile may come first.
  template <class Soon>
  void look_ahead(int buckets, Soon&& soon) {
    if (current_ == looked_ahead_from_) return;
    looked_ahead_from_ = current_;
    while (waiting_count_ > 0) file_waiting();  // so that the buckets' lists are complete
    for (int ahead = 1; ahead <= buckets; ++ahead) {
      for (std::uint32_t i = head_[bucket_index(current_ + ahead)]; i != none; i = item_[i].next)
        soon(i, ahead);
    }
    // The two buckets beyond, one step of each list a call: the next one's second record (its first
    // was asked for a call ago) and the one after's first. Two to four per cent more collisions a
    // second at 10^6 balls than the first records alone (median of alternating spans in one process).
    const std::uint32_t beyond = head_[bucket_index(current_ + buckets + 1)];
    if (beyond != none) {
      const std::uint32_t second = item_[beyond].next;
      if (second != none) detail::prefetch(&item_[second]);
    }
    const std::uint32_t further = head_[bucket_index(current_ + buckets + 2)];
    if (further != none) detail::prefetch(&item_[further]);
  }

  /// Asks memory for item i's record (a hint, as are the two below: nothing changes).
  void prefetch_record(std::uint32_t i) const { detail::prefetch(&item_[i]); }

  /// Asks memory for what taking item i out of its list writes: the neighbour before it or the list's
  /// head, and the neighbour after it. Reads item i's record, which should be in the caches already
  /// (prefetch_record).
  void prefetch_removal(std::uint32_t i) const {
    const Item& item = item_[i];
    if (item.bucket == front || item.bucket == waiting) return;  // in no list
    if (item.previous != none)
      detail::prefetch(&item_[item.previous]);
    else if (item.bucket != overflow_list)
      detail::prefetch(&head_[item.bucket]);
    if (item.next != none) detail::prefetch(&item_[item.next]);
  }

  /// Asks memory for what update(i, time) reads first: item i's record and, where `time` falls in a
  /// later bucket of this year, that bucket's head. Reads nothing of item i.
  void prefetch_update(std::uint32_t i, double time) const {
    detail::prefetch(&item_[i]);
    if (const std::optional<std::int64_t> b = bucket_this_year(time); b && *b > current_)
      detail::prefetch(&head_[bucket_index(*b)]);
  }

  /// The item with the earliest time (any one of equal times); none when every time is +∞.
  std::uint32_t earliest() {
    for (;;) {
      while (!front_.empty() && stale(front_.front())) {
        std::pop_heap(front_.begin(), front_.end(), later);
        front_.pop_back();
      }
      if (!front_.empty()) return front_.front().item;
      if (waiting_count_ > 0) {  // a later bucket's, filed before the front moves on
        file_waiting();
        continue;
      }
      if (in_ring_ == 0) {
        if (!next_year()) return none;
        continue;
      }
      if (++current_ == year_ + static_cast<std::int64_t>(mask_ + 1)) {
        next_year();
        continue;
      }
      std::uint32_t& head = head_[bucket_index(current_)];
      for (std::uint32_t i = head; i != none;) {
        const std::uint32_t next = item_[i].next;
        to_front(i);
        i = next;
      }
      head = none;
    }
  }

 private:
  static constexpr std::uint32_t overflow_list = none, front = none - 1, waiting = none - 2;
  // A bucket's width in mean spacings of the times. Two, with as many buckets as items (the same year
  // as one spacing and twice the buckets): half the ring's heads to miss in memory, and more of the
  // re-filed times land in the front bucket, whose heap costs no miss: large gases run a few percent
  // faster than with one spacing a bucket, small ones the same.
  static constexpr double spacings_a_bucket = 2;
  struct Item {
    double time = std::numeric_limits<double>::infinity();
    std::uint32_t next = none, previous = none;
    std::uint32_t bucket = overflow_list;  ///< the ring's index, front, or overflow_list
    std::uint32_t version = 0;             ///< counts the filings: tells a front entry it is stale
  };
  struct Entry {
    double time;
    std::uint32_t item, version;
  };
  static bool later(const Entry& a, const Entry& b) { return a.time > b.time; }
  bool stale(const Entry& e) const {
    return item_[e.item].version != e.version || item_[e.item].bucket != front;
  }

  std::size_t bucket_index(std::int64_t number) const { return static_cast<std::uint64_t>(number) & mask_; }
  std::int64_t bucket_number(double time) const {
    return static_cast<std::int64_t>(std::floor(time / width_));
  }
  std::uint32_t& list_of(const Item& item) {
    return item.bucket == overflow_list ? overflow_ : head_[item.bucket];
  }

  // The current bucket's items sit in a small heap (many may share one time: a lattice's first events).
  void to_front(std::uint32_t i) {
    Item& item = item_[i];
    item.bucket = front;
    front_.push_back({item.time, i, item.version});
    std::push_heap(front_.begin(), front_.end(), later);
  }

  // The number of the bucket `time` goes to in this year, the current one for a time before it; none
  // for a time beyond the year (+∞ and NaN included), which waits in the overflow list.
  std::optional<std::int64_t> bucket_this_year(double time) const {
    const double q = time / width_;
    if (!(q < static_cast<double>(year_ + static_cast<std::int64_t>(mask_ + 1)))) return std::nullopt;
    return std::max(current_, static_cast<std::int64_t>(std::floor(q)));
  }

  void file(std::uint32_t i, double time) {
    Item& item = item_[i];
    item.time = time;
    ++item.version;
    if (const std::optional<std::int64_t> b = bucket_this_year(time)) {
      ++in_ring_;
      if (*b == current_) return to_front(i);
      item.bucket = static_cast<std::uint32_t>(bucket_index(*b));
    } else {
      item.bucket = overflow_list;
    }
    std::uint32_t& head = list_of(item);
    item.previous = none;
    item.next = head;
    if (head != none) item_[head].previous = i;
    head = i;
  }

  void unfile(std::uint32_t i) {
    Item& item = item_[i];
    if (item.bucket == waiting) return;  // in no list and not counted: update() files it or queues it again
    if (item.bucket != overflow_list) --in_ring_;
    if (item.bucket == front) {  // its entry goes stale
      item.bucket = overflow_list;
      item.next = item.previous = none;
      return;
    }
    if (item.previous != none)
      item_[item.previous].next = item.next;
    else
      list_of(item) = item.next;
    if (item.next != none) item_[item.next].previous = item.previous;
  }

  // Files the item that has waited longest, unless it has been filed since (an item updated while it
  // waits may sit in the queue twice: the later entry finds it filed).
  void file_waiting() {
    const std::uint32_t i = waiting_[waiting_first_];
    waiting_first_ = (waiting_first_ + 1) % waiting_size;
    --waiting_count_;
    if (item_[i].bucket == waiting) file(i, item_[i].time);
  }

  // The next year: from the end of this one, or, with the ring empty, from the earliest waiting time
  // (no walk through empty years); the waiting times within it enter the ring. False when nothing waits
  // but +∞.
  bool next_year() {
    double earliest = std::numeric_limits<double>::infinity();
    for (std::uint32_t i = overflow_; i != none; i = item_[i].next)
      earliest = std::min(earliest, item_[i].time);
    if (in_ring_ == 0) {
      if (!std::isfinite(earliest)) return false;
      year_ = current_ = std::max(year_ + static_cast<std::int64_t>(mask_ + 1), bucket_number(earliest));
    } else {
      year_ += static_cast<std::int64_t>(mask_ + 1);
      current_ = year_;
    }
    std::uint32_t i = overflow_;
    overflow_ = none;
    while (i != none) {
      const std::uint32_t next = item_[i].next;
      file(i, item_[i].time);
      i = next;
    }
    return true;
  }

  // The deferred filings (defer_filings): four, oldest first; 10^6 disks run about 3 % faster with them.
  static constexpr std::size_t waiting_size = 4;
  bool defer_ = false;
  std::uint32_t waiting_[waiting_size] = {};
  std::size_t waiting_first_ = 0, waiting_count_ = 0;

  std::vector<double> ahead_;
  detail::Array<std::uint32_t> head_;
  detail::Array<Item> item_;
  std::vector<Entry> front_;
  std::uint32_t overflow_ = none;
  std::size_t mask_ = 0, in_ring_ = 0;
  std::int64_t year_ = 0, current_ = 0;
  std::int64_t looked_ahead_from_ = std::numeric_limits<std::int64_t>::min();
  double width_ = 1;
};

}  // namespace billiards::simulation
