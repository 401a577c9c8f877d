-- expect: 2: grid: goal 'c' has no body 'C'
require "grid" {
  "#######",
  "#@ $ .#",
  "#   c #",
  "#######",
}
