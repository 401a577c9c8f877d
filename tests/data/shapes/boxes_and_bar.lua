-- Two boxes to their goals and a bar down to its own, round a short wall.
-- Reference solution (fewest pushes, one body a push): 22 pushes: uuRRldRRURRRRRRRRdrUllllllllldRRRRRRurDD
require "grid" {
  "################",
  "#   .        . #",
  "# $  $         #",
  "#  AAA         #",
  "#@   ##        #",
  "#          aaa #",
  "################",
}
