-- expect: 2: grid: 2 boxes but 1 goals: each box ('$') needs a goal ('.')
require "grid" {
  "######",
  "#@$$.#",
  "######",
}
