-- One box hauled along a one-cell corridor and down round a turn.
-- Reference solution (the look-ahead's, one push per lattice step): 10 pushes: M1 +x 4.2 m, M1 -y 1.8
-- m.
require "grid" {
  "############",
  "########   #",
  "#@$        #",
  "######### ##",
  "        # #",
  "        #.#",
  "        ###",
}
