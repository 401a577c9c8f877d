-- Three boxes into a one-cell corridor of goals, furthest first.
-- Reference solution (the look-ahead's, one push per lattice step): 18 pushes: M1 +x 0.6 m, M1 -y 0.6
-- m, M1 +x 1.2 m, M2 +x 0.6 m, M3 -y 1.2 m, M2 +x 0.6 m, M3 -y 1.8 m, M2 -y 2.4 m, M1 +x 0.6 m, M1 -y
-- 1.2 m.
require "grid" {
  "##########",
  "#        #",
  "# $ $ $  #",
  "#   @    #",
  "###### ###",
  "     #.#",
  "     #.#",
  "     #.#",
  "     ###",
}
