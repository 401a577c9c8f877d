-- An obstacle in a doorway pushed through into the next room and out of the way first.
-- Reference solution (the look-ahead's, one push per lattice step): 7 pushes: O1 +x 1.8 m, M1 +x 2.4
-- m.
require "grid" {
  "##########",
  "#    #   #",
  "# @$ o . #",
  "#    #   #",
  "##########",
}
