-- Three boxes, each through a one-cell door into its own room.
-- Reference solution (the look-ahead's, one push per lattice step): 12 pushes: M1 +y 1.8 m, M2 +x 0.6
-- m, M2 +y 1.8 m, M3 +x 1.2 m, M3 +y 1.8 m.
require "grid" {
  "#############",
  "#   #   #   #",
  "# . # . # . #",
  "## ### ### ##",
  "#           #",
  "# $  $  $   #",
  "#     @     #",
  "#############",
}
