-- An obstacle in the box's corridor is pushed down into a niche from the loop above, then the box goes the whole way.
-- Reference solution (the look-ahead's, one push per lattice step): 10 pushes: M1 +x 1.8 m, O1 -y 0.6
-- m, M1 +x 3.6 m.
require "grid" {
  "#############",
  "#           #",
  "# #### #### #",
  "#@$   o    .#",
  "###### ######",
  "     ###",
}
