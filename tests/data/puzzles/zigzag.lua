-- A box down a zigzag of bends two cells wide.
-- Reference solution (the look-ahead's, one push per lattice step): 9 pushes: M1 +x 2.4 m, M1 -y 1.2
-- m, M1 +x 1.2 m, M1 -y 0.6 m.
require "grid" {
  "###########",
  "#####   ###",
  "#@ $    ###",
  "######    #",
  "######    #",
  "#######  .#",
  "###########",
}
