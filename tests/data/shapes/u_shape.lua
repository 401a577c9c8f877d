-- A U-shaped body of five cells to its goal.
-- Reference solution (fewest pushes, one body a push): 8 pushes: lluRRRuurDDDrdRR
require "grid" {
  "############",
  "#          #",
  "# U U   #  #",
  "# UUU   #  #",
  "#  @       #",
  "#####  u u #",
  "#      uuu #",
  "############",
}
