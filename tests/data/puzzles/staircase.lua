-- A box pushed up a staircase of single cells.
-- Reference solution (the look-ahead's, one push per lattice step): 11 pushes: M2 +y 0.6 m, M1 +y 0.6
-- m, M1 +x 0.6 m, M2 +x 0.6 m, M2 +y 1.2 m, M2 +x 1.8 m, M1 +y 0.6 m, M1 +x 0.6 m.
require "grid" {
  "########",
  "#    ..#",
  "#    ###",
  "#  $ #",
  "# $ ##",
  "#@ ##",
  "####",
}
