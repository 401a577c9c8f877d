#include "world_summary.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <numbers>

namespace physltl::app {

void print_world_summary(std::ostream& out, const scenario::World& world) {
  const auto& w = world.workspace;
  const auto& r = world.robot;
  fmt::print(out, "scenario   {}\n", world.source_file);
  fmt::print(out, "workspace  [{:g}, {:g}] x [{:g}, {:g}] m, floor friction {:g}\n", w.bounds.min.x(), w.bounds.max.x(),
             w.bounds.min.y(), w.bounds.max.y(), w.floor_friction);
  fmt::print(out, "robot      {} drive, r = {:g} m, {:g} kg, |F| <= {:g} N, v <= {:g} m/s", scenario::drive_name(r.drive),
             r.radius, r.mass, r.max_force, r.max_speed);
  if (r.drive == scenario::Drive::kDifferential) {
    fmt::print(out, ", turn <= {:g} deg/s, heading {:g} deg", r.max_turn_rate * 180.0 / std::numbers::pi,
               r.start_yaw * 180.0 / std::numbers::pi);
  }
  fmt::print(out, ", start ({:g}, {:g})\n", r.start.x(), r.start.y());
  fmt::print(out, "fixed      {} bodies\n", world.fixed_bodies.size());
  for (const auto& b : world.movable_bodies) {
    const auto& f = b.footprint;
    const geometry::Shape& shape = f.shape;
    const std::string size = scenario::shape_size_text(shape);
    fmt::print(out, "movable    {:<8} {}, {:g} kg, friction {:g}, at ({:g}, {:g})\n", b.name, size, b.mass, b.friction,
               f.pose.position.x(), f.pose.position.y());
  }
  for (const auto& g : world.regions) {
    const auto c = g.polygon.centroid();
    fmt::print(out, "region     {:<8} {} corners around ({:g}, {:g})\n", g.name, g.polygon.vertices.size(), c.x(), c.y());
  }
  fmt::print(out, "formula    {}\n", world.task.formula);
}

}  // namespace physltl::app
