-- Two boxes nose to tail in a one-cell corridor, their goals at its closed end: the robot cannot get
-- round either, so no box can be pushed alone; pushed end to end, both go in.
require "grid" {
  "########",
  "#..$$ @#",
  "########",
}
