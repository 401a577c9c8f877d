-- A box walked round: the robot goes round the block to push the box back west.
-- Reference solution (the look-ahead's, one push per lattice step): 3 pushes: M1 -x 1.8 m.
require "grid" {
  "#########",
  "#.  $  @#",
  "# ##### #",
  "#       #",
  "#########",
}
