-- A box pushed east along a corridor, then south round the corner into the goal.
require "grid" {
  "#######",
  "#     #",
  "#@ $  #",
  "#### ##",
  "   #.# ",
  "   ### ",
}
