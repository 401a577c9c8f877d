-- A 2x2 block down the left of a wall, then along the bottom to its goal.
-- Reference solution (fewest pushes, one body a push): 16 pushes: urDrrdLulDDDDlldRRRRRRRRRR
require "grid" {
  "################",
  "#              #",
  "# @BB          #",
  "#  BB       ## #",
  "#           #  #",
  "#   #########  #",
  "#              #",
  "#           bb #",
  "#           bb #",
  "#              #",
  "################",
}
