-- A T-shaped body of four cells to its goal.
-- Reference solution (fewest pushes, one body a push): 6 pushes: DDldRurDllddrrRR
require "grid" {
  "###########",
  "#  @      #",
  "#  TTT    #",
  "#   T  #  #",
  "#      #  #",
  "#  #  ttt #",
  "#      t  #",
  "###########",
}
