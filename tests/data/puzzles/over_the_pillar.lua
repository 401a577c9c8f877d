-- A pillar between the box and its goal: the robot pushes the box up a row, then along it.
-- Reference solution (the look-ahead's, one push per lattice step): 5 pushes: M1 +x 0.6 m, M1 +y 0.6
-- m, M1 +x 1.8 m.
require "grid" {
  "#########",
  "#     . #",
  "# $ #   #",
  "#@      #",
  "#########",
}
