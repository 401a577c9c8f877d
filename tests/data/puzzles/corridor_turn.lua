-- A box through a one-cell corridor and round a turn: the robot steps up to push it down.
-- Reference solution (the look-ahead's, one push per lattice step): 7 pushes: M1 +x 2.4 m, M1 -y 1.8
-- m.
require "grid" {
  "##########",
  "#####   ##",
  "#@ $    ##",
  "######  ##",
  "     ## ##",
  "     ##.##",
  "     #####",
}
