#pragma once
// The colours of the paper's figure (documented in docs/rendering.md; change both together).

#include "physltl/render/scene.h"

namespace physltl::render::palette {

inline constexpr Color kBackground{0.80f, 0.83f, 0.86f};
inline constexpr Color kFloor{0.94f, 0.94f, 0.92f};
inline constexpr Color kGrid{0.86f, 0.86f, 0.84f};  // 1 m lines
inline constexpr Color kDecomposition{0.70f, 0.74f, 0.82f};
inline constexpr Color kFixedBody{0.82f, 0.20f, 0.18f};
inline constexpr Color kMovableBody{0.20f, 0.42f, 0.85f};
inline constexpr Color kRobot{0.20f, 0.72f, 0.30f};
inline constexpr Color kRobotNose{0.08f, 0.30f, 0.12f};  // a differential robot's heading
inline constexpr Color kRegion{1.00f, 0.85f, 0.10f, 0.55f};
inline constexpr Color kRegionEdge{0.80f, 0.62f, 0.00f};
inline constexpr Color kAvoidedRegion{0.90f, 0.20f, 0.25f, 0.40f};  // a region the task never enters
inline constexpr Color kAvoidedRegionEdge{0.70f, 0.05f, 0.10f};
inline constexpr Color kActiveMRegion{1.00f, 0.50f, 0.00f, 0.45f};
inline constexpr Color kActiveMRegionEdge{0.85f, 0.35f, 0.00f};
inline constexpr Color kInactiveMRegion{0.45f, 0.45f, 0.52f, 0.22f};
inline constexpr Color kInactiveMRegionEdge{0.55f, 0.55f, 0.62f};
inline constexpr Color kPath{0.08f, 0.08f, 0.10f};
inline constexpr Color kPathHalo{1.00f, 1.00f, 1.00f};
inline constexpr Color kText{0.10f, 0.10f, 0.12f};
// Bodies a task wants somewhere, each in its own colour (then again from the first): clear of the boxes'
// blue, the robot's green, the regions' yellow and the walls' red.
inline constexpr Color kNamedBodies[] = {
    {0.93f, 0.52f, 0.08f}, {0.58f, 0.30f, 0.78f}, {0.05f, 0.62f, 0.66f}, {0.86f, 0.28f, 0.62f}, {0.45f, 0.30f, 0.15f}};
inline constexpr Color kGoalHolds{0.55f, 0.90f, 0.55f, 0.90f};  // the label of an object goal that holds
inline constexpr Color kPanel{1.00f, 1.00f, 1.00f, 0.80f};

}  // namespace physltl::render::palette
