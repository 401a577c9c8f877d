-- The warehouse (warehouse.lua) laid out the other way round for a robot that visits its corners: 200 boxes
-- in 10 columns of 20, the boxes of a column 0.4 m apart (no robot passes between them), 1 m aisles between
-- the columns, and lanes 1 m wide along all four walls. Visit three corners in order from the fourth:
-- F(a & F(b & F c)). The way along the walls pushes nothing; the straight way crosses the rows. A good
-- plan goes round.

params.columns = params.columns or 10
params.rows = params.rows or 20
params.gap = params.gap or 0.4
params.margin_x = params.margin_x or 1.2
params.margin_y = params.margin_y or 1.2
require "warehouse"
-- What `physltl-studio test scenarios/` holds this scenario to (docs/testing.md); the goldens are in goldens/warehouse_rows/.
expect { max_pushes = 0, max_motion_s = 68, tree = true, frames = { "last" } }
