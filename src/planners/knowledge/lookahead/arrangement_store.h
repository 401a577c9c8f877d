#pragma once
// The arrangements one push search meets (push_search.h), kept compactly so that a search can settle
// millions of them under a memory cap. An arrangement met but not yet settled is kept as its settled
// parent and the push that made it, 20 bytes whatever the number of bodies; only a settled one stores
// its bodies' places. Two arrangements are the same when their places, robot component and stage are:
// the set of those met holds arrangement numbers, hashed and compared through places rebuilt from the
// parent's, and is split into shards so that its growth never stops the search for long (one table of
// tens of millions of entries takes seconds to grow, past the time rule's second).

#include <absl/container/flat_hash_set.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace physltl::planners::knowledge::lookahead {

// Storage that grows a block at a time: nothing it holds is copied as it grows, and it is released in
// a few large pieces rather than millions of small ones (a search cut at its deadline must end at once).
template <typename T, std::size_t kBlock>
class BlockArray {
 public:
  explicit BlockArray(std::size_t width = 1) : width_(width) {}
  // Appends `width` uninitialised elements (a block is not zeroed: a small search touches little of
  // its first); returns the first.
  T* append() {
    if (size_ % kBlock == 0 && size_ / kBlock == blocks_.size()) blocks_.push_back(std::make_unique_for_overwrite<T[]>(kBlock * width_));
    return at(size_++);
  }
  void pop_back() { --size_; }
  T* at(std::size_t i) { return blocks_[i / kBlock].get() + i % kBlock * width_; }
  const T* at(std::size_t i) const { return blocks_[i / kBlock].get() + i % kBlock * width_; }
  std::size_t size() const { return size_; }
  std::size_t bytes() const { return blocks_.size() * kBlock * width_ * sizeof(T); }

 private:
  std::size_t width_;
  std::vector<std::unique_ptr<T[]>> blocks_;
  std::size_t size_ = 0;
};

class ArrangementStore {
 public:
  static constexpr std::uint32_t kStart = 0xFFFFFFFF;  // the parent of the first arrangement
  // An arrangement met: settled arrangement `parent`'s body `body` pushed in `direction` on to place
  // `to` (through a tunnel, several places on; by a goal macro, `macro`, along a way of its own), the
  // robot's component `robot` (its smallest place) and the task's stage `stage` after it.
  struct Met {
    std::uint32_t parent = kStart;
    std::int32_t robot = 0, stage = 0, to = 0;
    std::uint16_t body = 0;
    std::uint8_t direction = 0;
    bool macro = false;
  };
  // Throws std::length_error past 65,535 bodies (a Met names its body in 16 bits).
  explicit ArrangementStore(const std::vector<int>& start_cells);
  ArrangementStore(const ArrangementStore&) = delete;
  ArrangementStore& operator=(const ArrangementStore&) = delete;

  // Keeps `met` unless its arrangement was met before: its number or -1.
  int add(const Met& met);
  const Met& met(int m) const { return *mets_.at(static_cast<std::size_t>(m)); }
  // Settles met arrangement m with `cost` body steps: its settled number; `cells` gets its places.
  int settle(int m, int cost, std::vector<int>& cells);
  const int* settled_places(int s) const { return places_.at(static_cast<std::size_t>(s)); }
  int settled_met(int s) const { return settled_.at(static_cast<std::size_t>(s))->met; }
  int settled_cost(int s) const { return settled_.at(static_cast<std::size_t>(s))->cost; }
  std::size_t met_count() const { return mets_.size(); }
  // The memory it holds, counted from its tables' sizes (the same on any machine).
  std::size_t bytes() const;

 private:
  struct Settled {
    std::int32_t met = 0, cost = 0;
  };
  int place(const Met& met, std::size_t k) const;
  std::size_t hash(std::uint32_t m) const;
  bool same(std::uint32_t a, std::uint32_t b) const;

  struct Hash {
    const ArrangementStore* store;
    std::size_t operator()(std::uint32_t m) const { return store->hash(m); }
  };
  struct Equal {
    const ArrangementStore* store;
    bool operator()(std::uint32_t a, std::uint32_t b) const { return store->same(a, b); }
  };
  using Shard = absl::flat_hash_set<std::uint32_t, Hash, Equal>;
  static constexpr int kShardBits = 7;

  std::vector<int> start_;
  BlockArray<Met, 1 << 16> mets_;
  BlockArray<Settled, 1 << 14> settled_;
  BlockArray<int, 1 << 12> places_;  // a settled arrangement's places, one per body
  std::vector<Shard> shards_;
  // The hash of the arrangement being added, asked for twice (its shard, then the shard's table).
  mutable std::uint32_t hashed_ = kStart;
  mutable std::size_t hashed_value_ = 0;
};

}  // namespace physltl::planners::knowledge::lookahead
