-- A bar of three cells through a gap as wide as it is, onto its goal.
-- Reference solution (fewest pushes, one body a push): 7 pushes: lluRurDDDldRRR
require "grid" {
  "###########",
  "#         #",
  "# AAA  ## #",
  "#  @   #  #",
  "##    ##  #",
  "#     aaa #",
  "#         #",
  "###########",
}
