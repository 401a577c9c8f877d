-- Two boxes through a one-cell door into the far room, the lower one first.
-- Reference solution (the look-ahead's, one push per lattice step): 13 pushes: M1 +x 1.2 m, M2 +x 3.0
-- m, M1 -y 0.6 m, M1 +x 1.8 m, M1 +y 0.6 m, M1 +x 0.6 m.
require "grid" {
  "###########",
  "#    #    #",
  "# $  #  . #",
  "#@ $    . #",
  "#    #    #",
  "###########",
}
