-- expect: 2: grid: give the rows as a table of strings
require "grid" (5)
