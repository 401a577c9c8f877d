-- expect: 2: grid: nothing to push: no box ('$', '*') and no lettered body with a goal
require "grid" {
  "#####",
  "#@ .#",
  "#####",
}
