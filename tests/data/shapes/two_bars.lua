-- An upright and a lying bar, each to a goal of its own orientation.
-- Reference solution (fewest pushes, one body a push): 23 pushes:
-- drRRRurDldddlldRRRRRRdrUUUUlulllDDDldRRRRRR
require "grid" {
  "###############",
  "#@            #",
  "#  A      bbb #",
  "#  A          #",
  "#  A   #      #",
  "#      ##     #",
  "#   BBB     a #",
  "#           a #",
  "#           a #",
  "###############",
}
