-- Two obstacles pushed up into niches from the lane below before the box passes.
-- Reference solution (the look-ahead's, one push per lattice step): 12 pushes: M1 +x 1.2 m, O1 +y 0.6
-- m, M1 +x 2.4 m, O2 +y 0.6 m, M1 +x 2.4 m.
require "grid" {
  "##############",
  "##### ### ####",
  "#@$  o   o  .#",
  "#            #",
  "##############",
}
