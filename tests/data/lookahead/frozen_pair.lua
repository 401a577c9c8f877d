-- Two boxes against the bottom wall, M2 on its goal in the corner: M1 pushed next to it can move no more,
-- alone or pushed with M2 as a line (the line runs into the wall), and is not on its goal.
require "grid" {
  "#######",
  "#@    #",
  "#. $ *#",
  "#######",
}
