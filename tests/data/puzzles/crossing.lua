-- Two boxes whose corridors cross: one waits at the crossing's side.
-- Reference solution (the look-ahead's, one push per lattice step): 4 pushes: M1 +x 0.6 m, M1 +y 1.2
-- m, M2 -y 0.6 m.
require "grid" {
  "  #####",
  "  #.  #",
  "### # #",
  "#@$   #",
  "# # $##",
  "#   . #",
  "#######",
}
