#include "hexadapt/generate/cases.h"

#include <cmath>
#include <limits>

#include "hexadapt/core/error.h"

namespace hexadapt::generate {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

/// A point of the case's plane (2D: z = 0) or space.
Vec3 at(int dim, double x, double y, double z) {
  return {x, y, dim == 3 ? z : 0.0};
}

template <class P, class... A>
std::shared_ptr<const Primitive> make(A&&... a) {
  return std::make_shared<const P>(std::forward<A>(a)...);
}

CaseDefaults square(int n, double time = 0) {
  return {true, {n, n, 0}, {Vec3(0, 0, 0), Vec3(1, 1, 0)}, time};
}
CaseDefaults cube(int n, double time = 0) {
  return {true, {n, n, n}, {Vec3(0, 0, 0), Vec3(1, 1, 1)}, time};
}

Scene disk(int dim, std::uint64_t) {
  Scene s;
  s.layout.paint(1, make<Ball>(at(dim, 0.48, 0.53, 0.51), 0.31));
  return s;
}

// Disks (spheres) painted in order: each overlap belongs to the later one.
Scene venn_of(int dim, int count) {
  Scene s;
  const double dist = count == 3 ? 0.15 : 0.17, radius = count == 3 ? 0.25 : 0.24;
  for (int i = 0; i < count; ++i) {
    const double angle = pi / 2 + 2 * pi * i / count + (count == 4 ? 0.2 : 0.0);
    const double z = 0.5 + (count == 4 && dim == 3 ? 0.06 * (i % 2 ? 1 : -1) : 0.0);
    s.layout.paint(
        i + 1,
        make<Ball>(at(dim, 0.5 + dist * std::cos(angle), 0.5 + dist * std::sin(angle), z), radius));
  }
  return s;
}
Scene venn3(int dim, std::uint64_t) {
  return venn_of(dim, 3);
}
Scene venn4(int dim, std::uint64_t) {
  return venn_of(dim, 4);
}

// Zalesak's disk: radius 0.15 at (0.5, 0.75), a slot 0.05 wide cut up to y = 0.85.
Scene slotted_disk(int dim, std::uint64_t) {
  Scene s;
  s.layout.paint(1, make<Ball>(at(dim, 0.5, 0.75, 0.5), 0.15));
  s.layout.paint(0, make<Box>(Vec3(0.475, 0.5, -inf), Vec3(0.525, 0.85, inf)));
  return s;
}

Scene asteroid(int, std::uint64_t seed) {
  Scene s;
  s.layout.paint(1, make<NoisyBall>(Vec3(0.5, 0.5, 0.5), 0.3, 0.15, seed));
  s.layout.paint(2, make<Ball>(Vec3(0.54, 0.47, 0.5), 0.12));
  return s;
}

// Materials bottom (0), middle (1), top (2): the top is the background.
Scene layers(int dim, std::uint64_t) {
  Scene s{Layout(2), nullptr};
  s.layout.paint(1, make<BelowGraph>(dim, 0.65, 0.06, 1.5, 0.3));
  s.layout.paint(0, make<BelowGraph>(dim, 0.35, 0.05, 2.0, 1.1));
  return s;
}

// Galera, Maire, Breil 2010: left [0,1]x[0,3], bottom [1,7]x[0,1.5], top [1,7]x[1.5,3],
// rolled up clockwise by a vortex at the triple point (1, 1.5), one turn per unit time at
// its centre, support radius 1 (inside the domain: areas stay 3, 9, 9).
Scene triple_point(int, std::uint64_t) {
  Scene s;
  s.layout.paint(1, make<Box>(Vec3(1, -inf, -inf), Vec3(inf, 1.5, inf)));
  s.layout.paint(2, make<Box>(Vec3(1, 1.5, -inf), Vec3(inf, inf, inf)));
  s.flow = std::make_shared<const CompactVortex>(Vec3(1, 1.5, 0), 1.0, -2 * pi);
  return s;
}

// Three layers of height 1/3 on [0,2]x[0,1] and two counter-rotating vortices of radius
// 0.48 at (0.5, 0.5) and (1.5, 0.5).
Scene stir(int, std::uint64_t) {
  Scene s{Layout(2), nullptr};
  s.layout.paint(1, make<Box>(Vec3(-inf, -inf, -inf), Vec3(inf, 2.0 / 3.0, inf)));
  s.layout.paint(0, make<Box>(Vec3(-inf, -inf, -inf), Vec3(inf, 1.0 / 3.0, inf)));
  s.flow = std::make_shared<const SumFlow>(std::vector<std::shared_ptr<const Flow>>{
      std::make_shared<const CompactVortex>(Vec3(0.5, 0.5, 0), 0.48, 2 * pi),
      std::make_shared<const CompactVortex>(Vec3(1.5, 0.5, 0), 0.48, -2 * pi)});
  return s;
}

Scene vortex(int dim, std::uint64_t) {
  Scene s;
  if (dim == 2) {
    s.layout.paint(1, make<Ball>(Vec3(0.5, 0.75, 0), 0.15));
    s.flow = std::make_shared<const SingleVortex>(8.0);
  } else {
    s.layout.paint(1, make<Ball>(Vec3(0.35, 0.35, 0.35), 0.15));
    s.flow = std::make_shared<const Deformation3D>(3.0);
  }
  return s;
}

// Air (0), a pool below 0.35 (1) and a drop of radius 0.13 centred 0.66 high (2), in a
// circulation of radius 0.4 centred 0.42 high that pulls the drop down the axis.
Scene balldrop(int dim, std::uint64_t) {
  Scene s;
  s.layout.paint(1, make<BelowGraph>(dim, 0.35, 0.0, 1.0, 0.0));
  s.layout.paint(2, make<Ball>(dim == 3 ? Vec3(0.5, 0.5, 0.66) : Vec3(0.5, 0.66, 0), 0.13));
  s.flow = std::make_shared<const DropFlow>(
      dim, dim == 3 ? Vec3(0.5, 0.5, 0.42) : Vec3(0.5, 0.42, 0), 0.4, 0.8);
  return s;
}

std::vector<Case> make_cases() {
  const CaseDefaults none;
  const CaseDefaults tp{true, {140, 60, 0}, {Vec3(0, 0, 0), Vec3(7, 3, 0)}, 1.0};
  const CaseDefaults st{true, {128, 64, 0}, {Vec3(0, 0, 0), Vec3(2, 1, 0)}, 0.75};
  return {
      {"disk", "a disk of radius 0.31 (2D)", {"outside", "disk"}, square(64), none, false, disk},
      {"sphere",
       "a sphere of radius 0.31 (3D)",
       {"outside", "sphere"},
       none,
       cube(32),
       false,
       disk},
      {"venn",
       "three overlapping disks or spheres, later ones on top",
       {"outside", "a", "b", "c"},
       square(64),
       cube(32),
       false,
       venn3},
      {"venn4",
       "four overlapping disks or spheres: five materials",
       {"outside", "a", "b", "c", "d"},
       square(64),
       cube(32),
       false,
       venn4},
      {"slotted-disk",
       "Zalesak's slotted disk (a slotted sphere in 3D)",
       {"outside", "disk"},
       square(100),
       cube(48),
       false,
       slotted_disk},
      {"asteroid",
       "a sphere with seeded low-frequency surface noise and a core (3D)",
       {"space", "rock", "core"},
       none,
       cube(48),
       false,
       asteroid},
      {"layers",
       "three layers with wavy interfaces",
       {"bottom", "middle", "top"},
       square(64),
       cube(32),
       false,
       layers},
      {"triple-point",
       "the triple-point problem's three regions rolled up by a vortex",
       {"left", "bottom", "top"},
       tp,
       none,
       true,
       triple_point},
      {"stir",
       "three layers stirred by two counter-rotating vortices",
       {"bottom", "middle", "top"},
       st,
       none,
       true,
       stir},
      {"vortex",
       "a disk in the single-vortex flow (2D), a sphere in LeVeque's flow (3D)",
       {"outside", "fluid"},
       square(128, 3.0),
       cube(48, 1.5),
       true,
       vortex},
      {"balldrop",
       "a drop above a pool, pulled down by a circulation",
       {"air", "pool", "drop"},
       square(128, 0.5),
       cube(48, 0.5),
       true,
       balldrop},
  };
}

}  // namespace

const std::vector<Case>& cases() {
  static const std::vector<Case> all = make_cases();
  return all;
}

const Case& find_case(const std::string& name) {
  std::string known;
  for (const auto& c : cases()) {
    if (c.name == name) return c;
    known += (known.empty() ? "" : ", ") + c.name;
  }
  throw OptionError("unknown case '" + name + "' (known: " + known + ")");
}

}  // namespace hexadapt::generate
