-- A bar of two cells and a box end to end in a corridor whose far end the robot cannot reach: only the
-- robot pushing the bar, the bar pushing the box, gets the box to its goal at the end and the bar onto its
-- own behind it.
require "grid" {
  "#########",
  "#@ AA$ .#",
  "#########",
  goals = {
    "#########",
    "#    aa #",
    "#########",
  },
}
