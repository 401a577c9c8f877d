-- A 2x2 block in the box's row, pushed down into a niche first.
-- Reference solution (fewest pushes, one body a push): 9 pushes: dRRurrDulldRRRRRR
require "grid" {
  "############",
  "#@         #",
  "# $  BB   .#",
  "#    BB    #",
  "####    ####",
  "   #    #   ",
  "   ######   ",
}
