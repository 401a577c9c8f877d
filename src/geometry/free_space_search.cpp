#include "free_space_search.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

namespace physltl::geometry {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Where straight lines start: a point the path reached (`beam` zero), or the parallel lines square to a
// place's edge (`beam` their unit direction, `origin` a point of that edge).
struct Root {
  Vec2 origin = Vec2::Zero();
  Vec2 beam = Vec2::Zero();
  double g = 0.0;   // the path's length at `origin`
  int vertex = -1;  // the mesh vertex a point root is at; -1 for a beam

  bool is_beam() const { return beam.x() != 0.0 || beam.y() != 0.0; }
  double length_to(const Vec2& x) const { return is_beam() ? g + (x - origin).dot(beam) : g + (x - origin).norm(); }
  Vec2 ray_through(const Vec2& x) const { return is_beam() ? beam : Vec2(x - origin); }
  // The least length to a point of segment [a, b].
  double length_to_segment(const Vec2& a, const Vec2& b) const {
    if (is_beam()) return std::min(length_to(a), length_to(b));
    const Vec2 d = b - a;
    const double length2 = d.squaredNorm();
    const double t = length2 > 0 ? std::clamp((origin - a).dot(d) / length2, 0.0, 1.0) : 0.0;
    return g + (a + t * d - origin).norm();
  }
};

// The lines from `root` through [left, right] (left as the root sees it), an interval of edge `edge` of
// `triangle`, across which they go on.
struct Node {
  double f;          // the least length at a point of the interval
  long long order;   // of pushing: equal lengths come out in a fixed order
  Root root;
  Vec2 left, right;
  int triangle, edge;
};

struct Later {
  bool operator()(const Node& a, const Node& b) const { return a.f != b.f ? a.f > b.f : a.order > b.order; }
};

// Where a line through an interval leaves the triangle beyond it: across the far edge on the left (from
// the interval's left vertex to the opposite one), across the one on the right, or through the opposite
// vertex.
enum class Exit { kLeftEdge, kRightEdge, kOpposite };

class Search {
 public:
  Search(const FreeMesh& mesh, int source, const base::Deadline& deadline)
      : mesh_(mesh), deadline_(deadline), best_(mesh.place_vertex.size(), kInfinity), root_length_(mesh.vertices.size(), kInfinity),
        in_source_(mesh.triangles.size(), 0) {
    seed(source);
  }

  std::vector<double> run() {
    long long popped = 0;
    while (!open_.empty()) {
      const Node node = open_.top();
      open_.pop();
      if (++popped % 256 == 0) {
        deadline_.check();
        if (node.f >= *std::max_element(best_.begin(), best_.end())) break;  // every place at its final length
      }
      if (node.root.vertex >= 0 && node.root.g > root_length_[static_cast<size_t>(node.root.vertex)]) continue;  // rooted better since
      expand(node);
    }
    return best_;
  }

 private:
  const Vec2& at(int vertex) const { return mesh_.vertices[static_cast<size_t>(vertex)]; }

  void offer(int place, double length) { best_[static_cast<size_t>(place)] = std::min(best_[static_cast<size_t>(place)], length); }

  // The places of one point at `vertex`, reached at `length`.
  void offer_point_places(int vertex, double length) {
    if (!mesh_.point_place_at[static_cast<size_t>(vertex)]) return;
    for (size_t p = 0; p < mesh_.place_vertex.size(); ++p) {
      if (mesh_.place_vertex[p] == vertex) offer(static_cast<int>(p), length);
    }
  }

  void seed(int source) {
    const auto place = static_cast<size_t>(source);
    const int point = mesh_.place_vertex[place];
    if (point >= 0) {
      open_vertex(Root{at(point), Vec2::Zero(), 0.0, point});
      return;
    }
    for (int t : mesh_.place_triangles[place]) in_source_[static_cast<size_t>(t)] = 1;
    for (int t : mesh_.place_triangles[place]) {
      const FreeMesh::Triangle& triangle = mesh_.triangles[static_cast<size_t>(t)];
      for (int p : mesh_.triangle_places[static_cast<size_t>(t)]) offer(p, 0.0);
      for (int v : triangle.vertex) offer_point_places(v, 0.0);
      for (int e = 0; e < 3; ++e) {
        const int beyond = triangle.neighbour[static_cast<size_t>(e)];
        if (beyond < 0 || in_source_[static_cast<size_t>(beyond)]) continue;
        // Leaving the place across this edge: square to it from its inside, or from either end.
        const int from = triangle.vertex[static_cast<size_t>(e)], to = triangle.vertex[static_cast<size_t>((e + 1) % 3)];
        const Vec2 along = (at(to) - at(from)).normalized();
        push(Root{at(from), Vec2(along.y(), -along.x()), 0.0, -1}, t, e, at(to), at(from));
        for (int end : {from, to}) {
          if (root_length_[static_cast<size_t>(end)] > 0.0) open_vertex(Root{at(end), Vec2::Zero(), 0.0, end});
        }
      }
    }
  }

  // A path reached vertex root.vertex: every free triangle round it is in its sight.
  void open_vertex(const Root& root) {
    const auto v = static_cast<size_t>(root.vertex);
    root_length_[v] = root.g;
    for (int i = mesh_.incident_start[v]; i < mesh_.incident_start[v + 1]; ++i) see_triangle_from_corner(root, mesh_.incident[static_cast<size_t>(i)]);
  }

  // The whole of `triangle`, one of whose vertices is the root, is in the root's sight: the places in it
  // are reached, and the lines go on across its edge opposite the root.
  void see_triangle_from_corner(const Root& root, int triangle) {
    if (in_source_[static_cast<size_t>(triangle)]) return;  // a way through the source starts better at its far side
    const FreeMesh::Triangle& t = mesh_.triangles[static_cast<size_t>(triangle)];
    for (int p : mesh_.triangle_places[static_cast<size_t>(triangle)]) offer(p, root.g);
    for (int v : t.vertex) offer_point_places(v, root.length_to(at(v)));
    const int j = static_cast<int>(std::find(t.vertex.begin(), t.vertex.end(), root.vertex) - t.vertex.begin());
    const int far = (j + 1) % 3;
    push(root, triangle, far, at(t.vertex[static_cast<size_t>((j + 2) % 3)]), at(t.vertex[static_cast<size_t>(far)]));
  }

  // The lines from `root` through [left, right] on edge `edge` of `triangle` (left as the root sees it,
  // that is nearer the edge's second vertex) go on into the triangle across it.
  void push(const Root& root, int triangle, int edge, const Vec2& left, const Vec2& right) {
    const FreeMesh::Triangle& t = mesh_.triangles[static_cast<size_t>(triangle)];
    const int beyond = t.neighbour[static_cast<size_t>(edge)];
    if (beyond < 0 || in_source_[static_cast<size_t>(beyond)] || left == right) return;
    open_.push(Node{root.length_to_segment(left, right), order_++, root, left, right, beyond, t.neighbour_edge[static_cast<size_t>(edge)]});
  }

  // Where the line from `origin` along `direction` meets segment [from, to] (snapped to an end within a
  // rounding, so that an interval that ends at a vertex ends exactly there).
  static Vec2 exit_point(const Vec2& origin, const Vec2& direction, const Vec2& from, const Vec2& to) {
    const double denominator = cross(to - from, direction);
    if (denominator == 0.0) return from;
    const double u = std::clamp(cross(origin - from, direction) / denominator, 0.0, 1.0);
    if (u <= 1e-12) return from;
    if (u >= 1.0 - 1e-12) return to;
    return from + u * (to - from);
  }
  // Where the line from `origin` (on the entry edge a-b) along `direction` leaves the triangle a, b,
  // `opposite`: the side, and the point in `where`.
  static Exit exit_side(const Vec2& origin, const Vec2& direction, const Vec2& opposite, const Vec2& a, const Vec2& b, Vec2& where) {
    const double side = cross(direction, opposite - origin);
    const double margin = 1e-12 * direction.norm() * (opposite - origin).norm();
    if (side < -margin) return where = exit_point(origin, direction, a, opposite), Exit::kLeftEdge;
    if (side > margin) return where = exit_point(origin, direction, opposite, b), Exit::kRightEdge;
    return where = opposite, Exit::kOpposite;
  }

  void expand(const Node& node) {
    const FreeMesh::Triangle& t = mesh_.triangles[static_cast<size_t>(node.triangle)];
    const int k = node.edge, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    const int a = t.vertex[static_cast<size_t>(k)], b = t.vertex[static_cast<size_t>(k1)], o = t.vertex[static_cast<size_t>(k2)];
    const Vec2 &A = at(a), &B = at(b), &O = at(o);
    const Root& root = node.root;

    for (int p : mesh_.triangle_places[static_cast<size_t>(node.triangle)]) offer(p, node.f);
    const Vec2 left_ray = root.ray_through(node.left), right_ray = root.ray_through(node.right);
    for (int v : {a, b, o}) {
      const Vec2& x = at(v);
      if (cross(left_ray, x - node.left) <= 1e-12 * left_ray.norm() * (x - node.left).norm() &&
          cross(right_ray, x - node.right) >= -1e-12 * right_ray.norm() * (x - node.right).norm()) {
        offer_point_places(v, root.length_to(x));
      }
    }

    Vec2 left_exit, right_exit;
    const Exit left_side = exit_side(node.left, left_ray, O, A, B, left_exit);
    const Exit right_side = exit_side(node.right, right_ray, O, A, B, right_exit);
    // What the root sees: on the far edges between the two lines.
    if (left_side == Exit::kLeftEdge) push(root, node.triangle, k2, left_exit, right_side == Exit::kLeftEdge ? right_exit : O);
    if (right_side == Exit::kRightEdge) push(root, node.triangle, k1, left_side == Exit::kRightEdge ? left_exit : O, right_exit);
    // What it does not: past a corner at an end of the interval, the lines bend round it.
    if (node.left == A && mesh_.corner[static_cast<size_t>(a)] && left_side != Exit::kLeftEdge) {
      turn_round(node, a, left_ray, true, left_side == Exit::kRightEdge ? left_exit : O);
    }
    if (node.right == B && mesh_.corner[static_cast<size_t>(b)] && right_side != Exit::kRightEdge) {
      turn_round(node, b, right_ray, false, right_side == Exit::kLeftEdge ? right_exit : O);
    }
  }

  // The line along `ray` grazes `corner`, the interval's left (or right) end, and goes on into the node's
  // triangle, leaving it at `exit`. If something not free touches the corner on that line's left (right)
  // side, the part of the triangle beyond the line and the triangles round the corner up to that
  // something are in its shadow: reached only by a path that turns at the corner. Otherwise the root sees
  // them past the corner through other intervals.
  void turn_round(const Node& node, int corner, const Vec2& ray, bool left, const Vec2& exit) {
    const Vec2& C = at(corner);
    // Past the line's way back: the turn has gone half round without meeting anything.
    const auto past = [&](const Vec2& x) {
      const double side = cross(ray, x - C);
      return left ? (side < 0 || (side == 0 && (x - C).dot(ray) < 0)) : (side > 0 || (side == 0 && (x - C).dot(ray) < 0));
    };
    std::vector<int>& shadowed = shadowed_;
    shadowed.clear();
    int triangle = node.triangle;
    // Round the corner: anticlockwise from the triangle's far edge on the left, clockwise from the one on the right.
    int edge = left ? (node.edge + 2) % 3 : (node.edge + 1) % 3;
    const int round = mesh_.incident_start[static_cast<size_t>(corner) + 1] - mesh_.incident_start[static_cast<size_t>(corner)];
    for (int turns = 0;; ++turns) {
      const FreeMesh::Triangle& t = mesh_.triangles[static_cast<size_t>(triangle)];
      const int beyond = t.neighbour[static_cast<size_t>(edge)];
      if (beyond < 0) break;  // the corner's obstacle: it casts the shadow
      const FreeMesh::Triangle& next = mesh_.triangles[static_cast<size_t>(beyond)];
      const int shared = t.neighbour_edge[static_cast<size_t>(edge)];
      const int j = left ? shared : (shared + 1) % 3;  // the corner's place in `next`
      const int next_edge = left ? (j + 2) % 3 : j;
      const int other = next.vertex[static_cast<size_t>(left ? (j + 2) % 3 : (j + 1) % 3)];
      if (past(at(other)) || turns > round) return;  // (more turns than triangles round it: only by rounding)
      shadowed.push_back(beyond);
      triangle = beyond;
      edge = next_edge;
    }
    const Root turned{C, Vec2::Zero(), node.root.length_to(C), corner};
    if (turned.g >= root_length_[static_cast<size_t>(corner)]) return;  // reached as short or shorter before
    root_length_[static_cast<size_t>(corner)] = turned.g;
    const FreeMesh::Triangle& t = mesh_.triangles[static_cast<size_t>(node.triangle)];
    const Vec2& O = at(t.vertex[static_cast<size_t>((node.edge + 2) % 3)]);
    if (left) {
      push(turned, node.triangle, (node.edge + 1) % 3, O, exit);
    } else {
      push(turned, node.triangle, (node.edge + 2) % 3, exit, O);
    }
    for (int s : shadowed) see_triangle_from_corner(turned, s);
  }

  const FreeMesh& mesh_;
  const base::Deadline& deadline_;
  std::vector<double> best_;         // per place
  std::vector<double> root_length_;  // per vertex: the shortest path that turned there so far
  std::vector<char> in_source_;      // per triangle
  std::priority_queue<Node, std::vector<Node>, Later> open_;
  long long order_ = 0;
  std::vector<int> shadowed_;
};

}  // namespace

std::vector<double> distances_from_place(const FreeMesh& mesh, int source, const base::Deadline& deadline) {
  return Search(mesh, source, deadline).run();
}

}  // namespace physltl::geometry
