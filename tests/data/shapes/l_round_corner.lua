-- An L-shaped body of three cells round the end of a wall.
-- Reference solution (fewest pushes, one body a push): 5 pushes: ldRRRRurrrddlU
require "grid" {
  "##########",
  "#   #    #",
  "# @ # aa #",
  "# AA  a  #",
  "# A      #",
  "#     ####",
  "##########",
}
