-- An obstacle beside the box is pushed down into a niche first, so that the robot can push the box west.
-- Reference solution (the look-ahead's, one push per lattice step): 4 pushes: O1 -y 0.6 m, M1 -x 1.8
-- m.
require "grid" {
  "##########",
  "#####  ###",
  "#.  $o @ #",
  "##### ####",
  "    ###",
}
