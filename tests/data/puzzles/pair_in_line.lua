-- Two boxes in one corridor, each to the goal on its own side.
-- Reference solution (the look-ahead's, one push per lattice step): 6 pushes: M1 -x 1.8 m, M2 +x 1.8
-- m.
require "grid" {
  "###########",
  "#.  $@$  .#",
  "###########",
}
