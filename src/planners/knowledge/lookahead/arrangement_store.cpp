#include "arrangement_store.h"

#include <stdexcept>

namespace physltl::planners::knowledge::lookahead {
namespace {

// MurmurHash3's finaliser: every bit of the input moves about half the bits of the output, so that the
// table's slot (the high bits), its control byte (the low bits) and the shard (the top bits) all vary.
std::uint64_t finalise(std::uint64_t h) {
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdULL;
  h ^= h >> 33;
  h *= 0xc4ceb9fe1a85ec53ULL;
  h ^= h >> 33;
  return h;
}

}  // namespace

ArrangementStore::ArrangementStore(const std::vector<int>& start_cells)
    : start_(start_cells), places_(start_cells.size()) {
  if (start_cells.size() > 0xFFFF) throw std::length_error("the look-ahead names a body in 16 bits: over 65535 bodies on its lattice");
  shards_.reserve(std::size_t{1} << kShardBits);
  for (int i = 0; i < 1 << kShardBits; ++i) shards_.emplace_back(0, Hash{this}, Equal{this});
}

int ArrangementStore::place(const Met& met, std::size_t k) const {
  if (met.parent == kStart) return start_[k];
  return k == met.body ? met.to : settled_places(static_cast<int>(met.parent))[k];
}

std::size_t ArrangementStore::hash(std::uint32_t m) const {
  if (m == hashed_) return hashed_value_;
  const Met& arrangement = met(static_cast<int>(m));
  std::uint64_t h = finalise((static_cast<std::uint64_t>(static_cast<std::uint32_t>(arrangement.robot)) << 32) ^
                             static_cast<std::uint32_t>(arrangement.stage));
  for (std::size_t k = 0; k < start_.size(); ++k) {
    h = (h ^ static_cast<std::uint32_t>(place(arrangement, k))) * 0x9E3779B97F4A7C15ULL;
  }
  return finalise(h);
}

bool ArrangementStore::same(std::uint32_t a, std::uint32_t b) const {
  const Met& x = met(static_cast<int>(a));
  const Met& y = met(static_cast<int>(b));
  if (x.robot != y.robot || x.stage != y.stage) return false;
  for (std::size_t k = 0; k < start_.size(); ++k) {
    if (place(x, k) != place(y, k)) return false;
  }
  return true;
}

int ArrangementStore::add(const Met& met) {
  const auto m = static_cast<std::uint32_t>(mets_.size());
  *mets_.append() = met;
  hashed_value_ = hash(m);  // hashed_ is kStart between adds
  hashed_ = m;
  Shard& shard = shards_[hashed_value_ >> (64 - kShardBits)];
  const bool added = shard.insert(m).second;
  hashed_ = kStart;
  if (!added) {
    mets_.pop_back();
    return -1;
  }
  return static_cast<int>(m);
}

int ArrangementStore::settle(int m, int cost, std::vector<int>& cells) {
  const Met& arrangement = met(m);
  cells.resize(start_.size());
  for (std::size_t k = 0; k < start_.size(); ++k) cells[k] = place(arrangement, k);
  const auto s = static_cast<int>(settled_.size());
  *settled_.append() = {m, cost};
  std::copy(cells.begin(), cells.end(), places_.append());
  return s;
}

std::size_t ArrangementStore::bytes() const {
  std::size_t table = 0;
  for (const Shard& shard : shards_) table += shard.capacity() * (sizeof(std::uint32_t) + 1);
  return mets_.bytes() + settled_.bytes() + places_.bytes() + table;
}

}  // namespace physltl::planners::knowledge::lookahead
