#pragma once
// A set of a body's faces (scenario::face_count: a box's four sides, a polygon's sides, a cylinder's
// sectors) in one word: kappa holds one per movable body and is rebuilt after every physics step.

#include <cstdint>

namespace physltl::knowledge {

class FaceSet {
 public:
  static constexpr int kMaxFaces = 32;

  constexpr FaceSet() = default;
  // Faces 0 .. count - 1.
  static constexpr FaceSet first(int count) {
    return FaceSet(count >= kMaxFaces ? ~std::uint32_t{0} : (std::uint32_t{1} << count) - 1);
  }

  constexpr bool contains(int face) const { return (bits_ & bit(face)) != 0; }
  constexpr void insert(int face) { bits_ |= bit(face); }
  constexpr bool empty() const { return bits_ == 0; }
  constexpr bool operator==(const FaceSet&) const = default;

 private:
  constexpr explicit FaceSet(std::uint32_t bits) : bits_(bits) {}
  static constexpr std::uint32_t bit(int face) { return std::uint32_t{1} << static_cast<unsigned>(face); }
  std::uint32_t bits_ = 0;
};

}  // namespace physltl::knowledge
