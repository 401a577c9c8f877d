-- Two boxes pushed down onto their goals in an open 4 x 4 room.
require "grid" {
  "######",
  "#@   #",
  "# $$ #",
  "#   .#",
  "# .  #",
  "######",
}
