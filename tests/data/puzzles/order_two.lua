-- Two boxes into a dead-end pair of goals: the far goal first.
-- Reference solution (the look-ahead's, one push per lattice step): 4 pushes: M1 -y 1.2 m, M2 -y 1.2
-- m.
require "grid" {
  "#######",
  "#@    #",
  "# $$  #",
  "##  ###",
  " #..#",
  " ####",
}
