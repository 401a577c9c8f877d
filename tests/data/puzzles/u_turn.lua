-- A box taken round a U-turn: along a corridor, down through a bend, and back the other way.
-- Reference solution (the look-ahead's, one push per lattice step): 11 pushes: M1 +x 2.4 m, M1 -y 1.2
-- m, M1 -x 3.0 m.
require "grid" {
  "#########",
  "#####   #",
  "#@$     #",
  "######  #",
  "#.      #",
  "#####   #",
  "#########",
}
