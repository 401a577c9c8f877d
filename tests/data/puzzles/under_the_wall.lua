-- A box along a wall can only move along it, to the goal at the wall's end.
-- Reference solution (the look-ahead's, one push per lattice step): 5 pushes: M1 +x 3.0 m.
require "grid" {
  "#########",
  "# $    .#",
  "#  @    #",
  "#       #",
  "#########",
}
