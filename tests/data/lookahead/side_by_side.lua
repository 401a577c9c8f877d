-- Two boxes side by side in the middle of an open room, each a push from its goal: the walls leave room
-- to walk round, the boxes do not leave it between them.
require "grid" {
  "#########",
  "#       #",
  "#       #",
  "#  $.   #",
  "#  $.@  #",
  "#       #",
  "#       #",
  "#########",
}
