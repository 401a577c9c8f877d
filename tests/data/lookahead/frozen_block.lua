-- A 2x2 block in a room, its goal in the bottom right corner: pushed into any other corner it can never
-- leave it.
require "grid" {
  "########",
  "#@     #",
  "#  BB  #",
  "#  BB  #",
  "#    bb#",
  "#    bb#",
  "########",
}
