-- expect: 2: grid: body 'R' has a hole or cells meeting at a corner only
require "grid" {
  "#########",
  "#@ RRR  #",
  "#  R R  #",
  "#  RRR  #",
  "#########",
}
