#include "agglo/electrostatics/bem/sphere_triangulation.hpp"

#include <cstdint>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>

#include "agglo/electrostatics/bem/patches.hpp"

namespace agglo::es::bem {

namespace {

// A point counts as above a face plane when its height exceeds kEps. The points are on the unit
// sphere: round-off in a height is ~1e-15, while the nearest lattice point above a face of the
// hull of n = 10^5 Fibonacci points is ~1e-5 above it.
constexpr double kEps = 1e-12;

struct Face {
  std::array<int, 3> v{};      // vertices, counter-clockwise seen from outside
  std::array<int, 3> nb{};     // nb[e]: the face across edge v[e] -> v[(e + 1) % 3]
  Vec3 normal;                 // unit outward normal
  double offset = 0.0;         // normal . (a point of the plane)
  std::vector<int> conflicts;  // points not yet inserted that lie above this face (each on one list)
  bool alive = true;
};

class Hull {
 public:
  explicit Hull(std::span<const Vec3> p)
      : p_(p), owner_(p.size(), -1), from_(p.size(), -1), from_stamp_(p.size(), 0) {}

  std::vector<std::array<int, 3>> run() {
    const int n = static_cast<int>(p_.size());
    const std::array<int, 4> s = initial_simplex();
    for (int i = 0; i < n; ++i)
      if (i != s[0] && i != s[1] && i != s[2] && i != s[3]) assign(i, 0, static_cast<int>(faces_.size()));
    // Random insertion order (fixed seed, reproducible): expected O(n log n) work.
    std::vector<int> order;
    order.reserve(p_.size());
    for (int i = 0; i < n; ++i)
      if (owner_[i] >= 0) order.push_back(i);
    std::uint64_t state = 0x9e3779b97f4a7c15ULL;
    for (std::size_t k = order.size(); k > 1; --k) {
      state ^= state << 13;
      state ^= state >> 7;
      state ^= state << 17;
      std::swap(order[k - 1], order[state % k]);
    }
    for (const int i : order)
      if (owner_[i] >= 0) insert(i);
    std::vector<std::array<int, 3>> tri;
    for (const Face& f : faces_)
      if (f.alive) tri.push_back(f.v);
    return tri;
  }

 private:
  double height(int f, int i) const { return dot(faces_[f].normal, p_[i]) - faces_[f].offset; }

  int add_face(int a, int b, int c) {
    Face f;
    f.v = {a, b, c};
    const Vec3 nrm = cross(p_[b] - p_[a], p_[c] - p_[a]);
    const double len = norm(nrm);
    f.normal = len > 0.0 ? nrm / len : Vec3{};
    f.offset = dot(f.normal, p_[a] + p_[b] + p_[c]) / 3.0;
    faces_.push_back(std::move(f));
    mark_.push_back(0);
    return static_cast<int>(faces_.size()) - 1;
  }

  // Put point i on the conflict list of the face in [f_begin, f_end) it lies highest above; a
  // point above none of them is inside the hull (a duplicate) and is dropped.
  void assign(int i, int f_begin, int f_end) {
    int best = -1;
    double hmax = kEps;
    for (int f = f_begin; f < f_end; ++f) {
      const double h = height(f, i);
      if (h > hmax) {
        hmax = h;
        best = f;
      }
    }
    owner_[i] = best;
    if (best >= 0) faces_[best].conflicts.push_back(i);
  }

  std::array<int, 4> initial_simplex() {
    const int n = static_cast<int>(p_.size());
    auto argmax = [&](auto score) {
      int best = 0;
      double smax = -1.0;
      for (int i = 0; i < n; ++i)
        if (const double sc = score(i); sc > smax) {
          smax = sc;
          best = i;
        }
      return std::pair{best, smax};
    };
    const int i0 = 0;
    const auto [i1, d01] = argmax([&](int i) { return norm2(p_[i] - p_[i0]); });
    const Vec3 e1 = p_[i1] - p_[i0];
    const auto [i2, a012] = argmax([&](int i) { return norm2(cross(e1, p_[i] - p_[i0])); });
    const Vec3 nrm = cross(e1, p_[i2] - p_[i0]);
    const auto [i3, v0123] = argmax([&](int i) { return std::abs(dot(nrm, p_[i] - p_[i0])); });
    if (!(d01 > 1e-24 && a012 > 1e-24 && v0123 > 1e-14))
      throw std::invalid_argument("sphere_convex_hull: all " + std::to_string(n) +
                                  " points are coplanar (or coincide); no 3D hull");
    const std::array<int, 4> s{i0, i1, i2, i3};
    const std::array<std::array<int, 3>, 4> tri{{{i0, i1, i2}, {i0, i3, i1}, {i1, i3, i2}, {i0, i2, i3}}};
    const int opposite[4] = {i3, i2, i0, i1};
    for (int k = 0; k < 4; ++k) {
      const auto [a, b, c] = tri[k];
      const int f = add_face(a, b, c);
      if (height(f, opposite[k]) > 0.0) {  // orient outward: the fourth vertex must lie below
        faces_.pop_back();
        mark_.pop_back();
        add_face(a, c, b);
      }
    }
    for (int f = 0; f < 4; ++f)
      for (int e = 0; e < 3; ++e) {
        const int a = faces_[f].v[e], b = faces_[f].v[(e + 1) % 3];
        for (int g = 0; g < 4; ++g)
          for (int k = 0; k < 3; ++k)
            if (faces_[g].v[k] == b && faces_[g].v[(k + 1) % 3] == a) faces_[f].nb[e] = g;
      }
    return s;
  }

  void insert(int i) {
    // Visible region: the faces connected to the owner face that point i lies above.
    ++stamp_;
    visible_.clear();
    visible_.push_back(owner_[i]);
    mark_[owner_[i]] = stamp_;
    for (std::size_t k = 0; k < visible_.size(); ++k)
      for (const int g : faces_[visible_[k]].nb)
        if (mark_[g] != stamp_ && height(g, i) > kEps) {
          mark_[g] = stamp_;
          visible_.push_back(g);
        }
    // A cone of new faces over the horizon (the edges between visible and hidden faces).
    const int first_new = static_cast<int>(faces_.size());
    for (const int f : visible_)
      for (int e = 0; e < 3; ++e) {
        const int g = faces_[f].nb[e];
        if (mark_[g] == stamp_) continue;
        const int a = faces_[f].v[e], b = faces_[f].v[(e + 1) % 3];
        if (from_stamp_[a] == stamp_)
          throw std::runtime_error("sphere_convex_hull: visible region of point " + std::to_string(i) +
                                   " is not a disk (degenerate input)");
        const int nf = add_face(a, b, i);
        faces_[nf].nb[0] = g;
        for (int k = 0; k < 3; ++k)
          if (faces_[g].v[k] == b && faces_[g].v[(k + 1) % 3] == a) faces_[g].nb[k] = nf;
        from_[a] = nf;
        from_stamp_[a] = stamp_;
      }
    const int end_new = static_cast<int>(faces_.size());
    for (int nf = first_new; nf < end_new; ++nf) {  // edge b -> i of (a, b, i) meets i -> b of (b, c, i)
      const int b = faces_[nf].v[1];
      if (from_stamp_[b] != stamp_)
        throw std::runtime_error("sphere_convex_hull: open horizon at point " + std::to_string(i) +
                                 " (degenerate input)");
      faces_[nf].nb[1] = from_[b];
      faces_[from_[b]].nb[2] = nf;
    }
    int steps = 1;  // the horizon must be one loop (a visible region with a hole gives several)
    for (int nf = faces_[first_new].nb[1]; nf != first_new && steps <= end_new - first_new; nf = faces_[nf].nb[1])
      ++steps;
    if (steps != end_new - first_new)
      throw std::runtime_error("sphere_convex_hull: horizon of point " + std::to_string(i) +
                               " is not one loop (degenerate input)");
    // Retire the visible faces and hand their conflict points to the new faces.
    owner_[i] = -1;
    for (const int f : visible_) {
      faces_[f].alive = false;
      std::vector<int> orphans;
      orphans.swap(faces_[f].conflicts);
      for (const int j : orphans)
        if (j != i) assign(j, first_new, end_new);
    }
  }

  std::span<const Vec3> p_;
  std::vector<Face> faces_;
  std::vector<int> owner_;       // per point: the face whose conflict list holds it, -1 once inserted
  std::vector<int> mark_;        // per face: stamp of the insertion that found it visible
  std::vector<int> from_;        // per vertex: new face whose horizon edge starts there
  std::vector<int> from_stamp_;  // per vertex: stamp of the insertion that set from_
  std::vector<int> visible_;
  int stamp_ = 0;
};

}  // namespace

std::vector<std::array<int, 3>> sphere_convex_hull(std::span<const Vec3> unit_points) {
  if (unit_points.size() < 4)
    throw std::invalid_argument("sphere_convex_hull: need at least 4 points (got " +
                                std::to_string(unit_points.size()) + ")");
  return Hull(unit_points).run();
}

const std::vector<std::array<int, 3>>& fibonacci_sphere_triangles(int n) {
  static std::mutex mutex;
  static std::map<int, std::vector<std::array<int, 3>>> cache;  // nodes never move: references stay valid
  const std::lock_guard lock(mutex);
  auto it = cache.find(n);
  if (it == cache.end()) {
    const std::vector<Vec3> u = fibonacci_sphere(n);
    it = cache.emplace(n, sphere_convex_hull(u)).first;
  }
  return it->second;
}

}  // namespace agglo::es::bem
