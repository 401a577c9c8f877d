#pragma once
// The four sides of a box, as a set, and what pushing from a side means geometrically.

#include "physltl/geometry/shapes.h"
#include "physltl/scenario/world.h"

#include <array>
#include <cstdint>

namespace physltl::knowledge {

using scenario::Side;

inline constexpr std::array<Side, 4> kAllSides = {Side::kMinusX, Side::kPlusX, Side::kMinusY, Side::kPlusY};

// A set of sides in a byte: kappa holds one per movable body and is rebuilt after every physics step.
class SideSet {
 public:
  constexpr SideSet() = default;
  static constexpr SideSet all() { return SideSet(0b1111); }

  constexpr bool contains(Side s) const { return (bits_ & bit(s)) != 0; }
  constexpr void insert(Side s) { bits_ |= bit(s); }
  constexpr bool empty() const { return bits_ == 0; }
  constexpr bool is_all() const { return bits_ == all().bits_; }
  constexpr bool operator==(const SideSet&) const = default;

 private:
  constexpr explicit SideSet(std::uint8_t bits) : bits_(bits) {}
  static constexpr std::uint8_t bit(Side s) { return static_cast<std::uint8_t>(1u << static_cast<unsigned>(s)); }
  std::uint8_t bits_ = 0;
};

// Unit normal of a side pointing away from the box, in the box's own frame.
geometry::Vec2 outward_normal(Side side);

// The direction, in the world frame, a box at `body_pose` moves when the robot pushes it from `side`:
// the robot stands on that side and pushes towards the opposite one.
geometry::Vec2 push_direction(Side side, const geometry::Pose2& body_pose);

}  // namespace physltl::knowledge
