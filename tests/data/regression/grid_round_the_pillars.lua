-- A box between two pillars: pushed north out of them, then west onto the goal from the east, which the
-- robot reaches round the pillar.
require "grid" {
  "#######",
  "#.    #",
  "# #$# #",
  "#  @  #",
  "#######",
}
