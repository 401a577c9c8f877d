-- A 3x3 block and a bar: the block must go right before the bar can go down past it.
-- Reference solution (fewest pushes, one body a push): 21 pushes: rRRRRRRRurDDDDullllllldRRRRRdddrUUluRRR
require "grid" {
  "################",
  "#              #",
  "# @ BBB        #",
  "#   BBB      a #",
  "#   BBB      a #",
  "#    A       a #",
  "#    A     bbb #",
  "#    A     bbb #",
  "#          bbb #",
  "################",
}
