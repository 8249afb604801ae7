// Room for the pairs that the broad phase's pieces find (sim/contact/triangle_contact.cpp,
// gather_pairs): one pool of chunks of kChunk pairs, which the pieces take as they fill them, each
// piece's chunks linked in order. A piece then needs no room of its own, so how the pairs spread
// over the hundreds of pieces does not matter: the pool grows only when all of them together
// find more pairs than it holds (the step loop allocates nothing once a scene has settled).
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sim/contact/stray_bounds.hpp"

namespace clothlab {

class PairPool {
 public:
  static constexpr std::size_t kChunk = 64;
  // One piece's pairs: its chunks, first to last.
  struct List {
    std::int32_t head = -1, tail = -1;
    std::size_t size = 0;
  };

  // Room for `pairs` in all, and for a partly filled last chunk in each of `pieces`.
  void reserve(std::size_t pairs, std::size_t pieces) {
    const std::size_t chunks = (pairs + kChunk - 1) / kChunk + pieces;
    slots_.resize(chunks * kChunk);
    next_.resize(chunks);
    pairs_ = pairs;
    pieces_ = pieces;
  }
  // Twice the room (after a gather ran out of it).
  void grow() { reserve(2 * std::max<std::size_t>(pairs_, kChunk), pieces_); }
  // Every chunk free again; the lists taken before are void.
  void clear() {
    used_.store(0, std::memory_order_relaxed);
    exhausted_.store(false, std::memory_order_relaxed);
  }
  bool exhausted() const { return exhausted_.load(std::memory_order_relaxed); }

  // Appends p to the list (from any thread, each list from one); false when no chunk was left.
  bool push(List& list, const ContactPair& p) {
    if (list.size % kChunk == 0) {
      const std::int32_t c = used_.fetch_add(1, std::memory_order_relaxed);
      if (std::size_t(c) >= next_.size()) {
        exhausted_.store(true, std::memory_order_relaxed);
        return false;
      }
      next_[std::size_t(c)] = -1;
      (list.tail >= 0 ? next_[std::size_t(list.tail)] : list.head) = c;
      list.tail = c;
    }
    slots_[std::size_t(list.tail) * kChunk + list.size % kChunk] = p;
    ++list.size;
    return true;
  }

  // Appends the list's pairs, in the order pushed, to out.
  void append_to(const List& list, std::vector<ContactPair>& out) const {
    std::size_t left = list.size;
    for (std::int32_t c = list.head; left > 0; c = next_[std::size_t(c)]) {
      const auto first = slots_.begin() + long(std::size_t(c) * kChunk);
      const std::size_t n = std::min(left, kChunk);
      out.insert(out.end(), first, first + long(n));
      left -= n;
    }
  }

 private:
  std::vector<ContactPair> slots_;
  std::vector<std::int32_t> next_;  // per chunk: the next chunk of its list, or -1
  std::atomic<std::int32_t> used_{0};
  std::atomic<bool> exhausted_{false};
  std::size_t pairs_ = 0, pieces_ = 0;
};

}  // namespace clothlab
