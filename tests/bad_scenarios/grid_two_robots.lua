-- expect: 2: grid: a second robot in row 3 (the first is in row 2)
require "grid" {
  "#####",
  "#@$.#",
  "#@  #",
  "#####",
}
