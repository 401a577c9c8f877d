-- Two boxes, each down its own corridor, the robot crossing between them.
-- Reference solution (the look-ahead's, one push per lattice step): 8 pushes: M1 -x 0.6 m, M1 -y 1.8
-- m, M2 +x 0.6 m, M2 -y 1.8 m.
require "grid" {
  "###########",
  "#@        #",
  "# $     $ #",
  "# ####### #",
  "# #     # #",
  "#.#     #.#",
  "###     ###",
}
