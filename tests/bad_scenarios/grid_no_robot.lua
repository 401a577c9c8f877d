-- expect: 2: grid: no robot: put '@' (or '+' on a goal) in a row
require "grid" {
  "#####",
  "# $.#",
  "#####",
}
