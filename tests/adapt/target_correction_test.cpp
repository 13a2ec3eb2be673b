// Target correction (paper sec. 5.3): known answers on a plane model built by hand and on the
// model the reconstruction extracts from a sphere; the surface quality metric; the model
// search against a linear scan.
#include "hexadapt/adapt/target_correction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "hexadapt/adapt/adapt.h"
#include "hexadapt/adapt/model_projection.h"
#include "hexadapt/core/error.h"
#include "hexadapt/mesh/structured.h"
#include "hexadapt/reconstruct/reconstruct.h"
#include "reconstruct/cases.h"

namespace hexadapt {
namespace {

using reconstruct::InterfaceModel;

TEST(SurfaceQuadQuality, KnownAnswers) {
  EXPECT_NEAR(surface_quad_quality({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}), 1,
              1e-14);
  // Any plane, either orientation.
  EXPECT_NEAR(surface_quad_quality({Vec3(0, 0, 0), Vec3(0, 0, 2), Vec3(1, 0, 2), Vec3(1, 0, 0)}), 1,
              1e-14);
  // A rhombus with 60 degree corners: sin(60).
  const double c = 0.5, s = std::sqrt(3.0) / 2;
  EXPECT_NEAR(surface_quad_quality({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1 + c, s, 0), Vec3(c, s, 0)}),
              s, 1e-14);
  // A dart: the reflex corner is negative.
  EXPECT_LT(surface_quad_quality({Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0.3, 0.3, 0), Vec3(0, 2, 0)}), 0);
  // Degenerate: a repeated corner.
  EXPECT_EQ(surface_quad_quality({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}), -1);
}

TEST(ModelProjection, ClosestPointOnTriangle) {
  const Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  EXPECT_TRUE(closest_point_on_triangle(Vec3(0.5, 0.5, 3), a, b, c).isApprox(Vec3(0.5, 0.5, 0)));
  EXPECT_TRUE(closest_point_on_triangle(Vec3(-1, -1, 1), a, b, c).isApprox(a));
  EXPECT_TRUE(closest_point_on_triangle(Vec3(3, -1, 0), a, b, c).isApprox(b));
  EXPECT_TRUE(closest_point_on_triangle(Vec3(1, -1, 0), a, b, c).isApprox(Vec3(1, 0, 0)));
  EXPECT_TRUE(closest_point_on_triangle(Vec3(2, 2, 0), a, b, c).isApprox(Vec3(1, 1, 0)));
  EXPECT_TRUE(closest_point_on_triangle(Vec3(-1, 1, 5), a, b, c).isApprox(Vec3(0, 1, 0)));
}

// The plane z = height over [0, n]^2 as quads of side h, pair {0, 1}; its border as curves.
InterfaceModel plane_model(int n, double height, int per_unit = 2) {
  InterfaceModel m;
  m.dim = 3;
  const int k = n * per_unit;
  const double h = 1.0 / per_unit;
  auto id = [&](int i, int j) { return static_cast<index_t>(i + (k + 1) * j); };
  for (int j = 0; j <= k; ++j)
    for (int i = 0; i <= k; ++i) m.points.emplace_back(i * h, j * h, height);
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i) {
      m.facets.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      m.facet_materials.push_back({0, 1});
    }
  for (int i = 0; i < k; ++i) {
    m.curves.push_back({id(i, 0), id(i + 1, 0)});
    m.curves.push_back({id(i, k), id(i + 1, k)});
    m.curves.push_back({id(0, i), id(0, i + 1)});
    m.curves.push_back({id(k, i), id(k, i + 1)});
  }
  return m;
}

struct PlaneCase {
  HexMesh mesh = make_hex_grid(6, 6, 6);
  IdVector<CellId, int> material;
  IdVector<NodeId, NodeConstraint> boundary;
  Targets targets;
};

// Material 1 above z = 3; the interface nodes' targets at z = 2.6 plus noise that keeps
// boundary nodes on the boundary.
PlaneCase plane_case(double noise, unsigned seed) {
  PlaneCase c;
  for (CellId id : id_range<CellId>(c.mesh.n_cells()))
    c.material.push_back(cell_centroid(c.mesh, id).z() > 3 ? 1 : 0);
  c.boundary = boundary_constraints(c.mesh);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-noise, noise);
  const auto nn = static_cast<std::size_t>(c.mesh.n_nodes());
  c.targets.has.assign(nn, 0);
  c.targets.position.assign(nn, Vec3::Zero());
  c.targets.interface.assign(nn, NodeConstraint{});
  for (NodeId v : id_range<NodeId>(c.mesh.n_nodes())) {
    const Vec3 p = c.mesh.point(v);
    c.targets.position[v] = p;
    if (p.z() != 3) continue;
    c.targets.has[v] = 1;
    const Vec3 shake(u(rng), u(rng), u(rng));
    c.targets.position[v] = Vec3(p.x(), p.y(), 2.6) + c.boundary[v].project(shake);
  }
  return c;
}

TEST(TargetCorrection, NoisyPlaneTargetsLandOnThePlaneAsGoodQuads) {
  PlaneCase c = plane_case(0.35, 7);
  const InterfaceModel model = plane_model(6, 2.6);
  const auto r = correct_targets(c.mesh, c.material, c.boundary, model, c.targets);
  ASSERT_TRUE(r.ran) << r.skipped;
  EXPECT_EQ(r.n_faces, 36);
  EXPECT_EQ(r.n_surface_nodes, 25);  // the 5 x 5 inner nodes; the border ones are curve nodes
  EXPECT_EQ(r.n_curve_nodes, 24);
  EXPECT_EQ(r.n_unprojected, 0);
  EXPECT_EQ(r.n_off_model, 0);
  for (NodeId v : id_range<NodeId>(c.mesh.n_nodes())) {
    if (!c.targets.has[v]) continue;
    const Vec3& t = c.targets.position[v];
    const Vec3& p = c.mesh.point(v);
    EXPECT_NEAR(t.z(), 2.6, 1e-12) << v.value();
    for (int a = 0; a < 2; ++a) {
      EXPECT_GE(t[a], -1e-12);
      EXPECT_LE(t[a], 6 + 1e-12);
      if (p[a] == 0 || p[a] == 6) {
        EXPECT_NEAR(t[a], p[a], 1e-12) << "left the boundary";
      }
    }
  }
  EXPECT_LT(r.min_quality_before, 0.6);
  EXPECT_GE(r.min_quality_after, r.min_quality_projected);
  EXPECT_GT(r.min_quality_after, 0.9);
  EXPECT_GT(r.mean_displacement, 0);
  EXPECT_LE(r.max_displacement, 0.35 * std::sqrt(3.0) + 1.0);
}

TEST(TargetCorrection, ExactTargetsStay) {
  PlaneCase c = plane_case(0, 1);
  const IdVector<NodeId, Vec3> before = c.targets.position;
  const auto r = correct_targets(c.mesh, c.material, c.boundary, plane_model(6, 2.6), c.targets);
  ASSERT_TRUE(r.ran);
  EXPECT_NEAR(r.min_quality_before, 1, 1e-12);
  EXPECT_NEAR(r.min_quality_after, 1, 1e-12);
  EXPECT_LT(r.max_displacement, 1e-12);
  for (NodeId v : id_range<NodeId>(c.mesh.n_nodes()))
    EXPECT_LT((c.targets.position[v] - before[v]).norm(), 1e-12);
}

TEST(TargetCorrection, NodesFarFromTheModelKeepTheirTargets) {
  PlaneCase c = plane_case(0.2, 3);
  const IdVector<NodeId, Vec3> before = c.targets.position;
  const auto r = correct_targets(c.mesh, c.material, c.boundary, plane_model(6, -5.0), c.targets);
  EXPECT_EQ(r.n_unprojected, 49);
  for (NodeId v : id_range<NodeId>(c.mesh.n_nodes())) EXPECT_EQ(c.targets.position[v], before[v]);
}

TEST(TargetCorrection, WrongMaterialPairIsNotUsed) {
  PlaneCase c = plane_case(0.2, 3);
  InterfaceModel model = plane_model(6, 2.6);
  for (auto& m : model.facet_materials) m = {0, 2};
  model.curves.clear();
  const auto r = correct_targets(c.mesh, c.material, c.boundary, model, c.targets);
  EXPECT_EQ(r.n_unprojected, 49);
}

struct SphereCase {
  testcase::Case<HexMesh> in;
  IdVector<CellId, int> material;
  reconstruct::Reconstruction rec;
  Vec3 centre{5.1, 4.9, 5.05};
  double radius = 3.2;
};

SphereCase sphere_case(int n = 10, double radius = 3.2) {
  SphereCase s;
  s.centre = Vec3(0.51, 0.49, 0.505) * n;
  s.radius = radius;
  const Vec3 c = s.centre;
  const double r = s.radius;
  s.in = testcase::make_case(make_hex_grid(n, n, n), 2,
                             [c, r](const Vec3& p) { return (p - c).norm() < r ? 1 : 0; });
  for (int m : s.in.majority) s.material.push_back(m);
  s.rec = reconstruct::reconstruct(s.in.mesh, s.in.fractions, s.in.majority, {});
  return s;
}

// Linear scan: distance from x to the model facets of pair {0, 1}.
double distance_to_model(const InterfaceModel& m, const Vec3& x) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < m.facets.size(); ++f) {
    if (m.facet_materials[f] != std::array<int, 2>{0, 1}) continue;
    auto p = [&](int k) { return m.points[static_cast<std::size_t>(m.facets[f][static_cast<std::size_t>(k)])]; };
    best = std::min({best, (closest_point_on_triangle(x, p(0), p(1), p(2)) - x).norm(),
                     (closest_point_on_triangle(x, p(0), p(2), p(3)) - x).norm()});
  }
  return best;
}

TEST(ModelProjection, AgreesWithALinearScan) {
  const SphereCase s = sphere_case();
  const ModelProjection projection(s.rec.model, 0.7);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 10);
  int found = 0;
  for (int i = 0; i < 300; ++i) {
    const Vec3 x(u(rng), u(rng), u(rng));
    const double want = distance_to_model(s.rec.model, x);
    const auto got = projection.on_surface(x, 1, 0, 1.2);
    if (want < 1.2 - 1e-9) {
      ASSERT_TRUE(got.has_value()) << i;
      EXPECT_NEAR((*got - x).norm(), want, 1e-12);
      EXPECT_LT(distance_to_model(s.rec.model, *got), 1e-12);
      ++found;
    } else if (want > 1.2 + 1e-9) {
      EXPECT_FALSE(got.has_value()) << i;
    }
  }
  EXPECT_GT(found, 30);
}

TEST(TargetCorrection, SphereTargetsLieOnTheReconstructedModel) {
  const SphereCase s = sphere_case();
  const auto boundary = boundary_constraints(s.in.mesh);
  for (double noise : {0.0, 0.3}) {
    Targets t = compute_targets(s.in.mesh, s.in.fractions, s.material, boundary);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-noise, noise);
    for (NodeId v : id_range<NodeId>(s.in.mesh.n_nodes()))
      if (t.has[v]) t.position[v] += Vec3(u(rng), u(rng), u(rng));
    const auto r = correct_targets(s.in.mesh, s.material, boundary, s.rec.model, t);
    ASSERT_TRUE(r.ran);
    EXPECT_EQ(r.n_curve_nodes + r.n_fixed_nodes, 0);  // a closed surface inside the domain
    EXPECT_EQ(r.n_unprojected, 0);
    EXPECT_GE(r.min_quality_after, r.min_quality_projected);
    if (noise > 0) {
      EXPECT_GT(r.min_quality_after, r.min_quality_before + 0.2) << "noise " << noise;
    } else {
      EXPECT_GE(r.min_quality_after, r.min_quality_before - 1e-12);
    }
    // Off the model: only the few nodes the result names (a projection would have made
    // one of their quads poor), none without noise.
    index_t off = 0, n = 0;
    for (NodeId v : id_range<NodeId>(s.in.mesh.n_nodes())) {
      if (!t.has[v]) continue;
      ++n;
      off += distance_to_model(s.rec.model, t.position[v]) > 1e-9;
      // The pixelated model is within about a pixel diagonal of the sphere.
      EXPECT_NEAR((t.position[v] - s.centre).norm(), s.radius, 0.5) << v.value();
    }
    EXPECT_EQ(off, r.n_off_model);
    EXPECT_LE(off, noise > 0 ? n / 20 : 0);
  }
}

TEST(TargetCorrection, GuaranteedPipelineRunsItWhenAskedWithAModelOnly) {
  const SphereCase s = sphere_case(7, 2.2);
  AdaptOptions o;
  EXPECT_EQ(adapt(s.in.mesh, s.in.fractions, s.material, o, &s.rec.model).correction.skipped,
            "disabled");  // off by default
  o.correction.enabled = true;
  o.cavity.range = 0;  // the wiring is under test here, not the later steps
  o.max_loops = 2;
  const auto with = adapt(s.in.mesh, s.in.fractions, s.material, o, &s.rec.model);
  EXPECT_TRUE(with.correction.ran);
  bool step = false;
  for (const auto& st : with.steps) step |= st.name == "correct";
  EXPECT_TRUE(step);
  EXPECT_GE(with.min_quality, o.threshold);
  EXPECT_GE(with.correction.min_quality_after, with.correction.min_quality_projected);
  // The output's targets are the corrected ones.
  for (NodeId v : id_range<NodeId>(s.in.mesh.n_nodes()))
    if (with.has_target[v]) {
      EXPECT_LT(distance_to_model(s.rec.model, with.target[v]), 1e-9);
    }

  const auto without = adapt(s.in.mesh, s.in.fractions, s.material, o);
  EXPECT_FALSE(without.correction.ran);
  EXPECT_EQ(without.correction.skipped, "no model given");
  o.correction.enabled = false;
  EXPECT_EQ(adapt(s.in.mesh, s.in.fractions, s.material, o, &s.rec.model).correction.skipped,
            "disabled");
}

TEST(TargetCorrection, ModelWithForeignMaterialsIsRefused) {
  const SphereCase s = sphere_case(5, 1.6);
  InterfaceModel model = s.rec.model;
  model.facet_materials[0] = {0, 5};
  EXPECT_THROW(adapt(s.in.mesh, s.in.fractions, s.material, {}, &model), InputError);
}

TEST(TargetCorrection, BadOptionsAreRefused) {
  AdaptOptions o;
  o.correction.relaxation = 0;
  PlaneCase c = plane_case(0, 1);
  EXPECT_THROW(check_options(o.correction), OptionError);
  EXPECT_THROW(correct_targets(c.mesh, c.material, c.boundary, plane_model(6, 2.6), c.targets,
                               o.correction),
               OptionError);
}

}  // namespace
}  // namespace hexadapt
