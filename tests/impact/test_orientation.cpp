// Orientation of the built-in agglomerates (orientation.hpp, agglomerate.orientation): every
// orientation keeps the contacts at the JKR equilibrium overlap, the centroid at the origin and the
// charges on their particles, and puts the hit edge, face or vertex where the header says; the
// config key is checked and stays out of the resolved config when absent.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "agglo/core/config.hpp"
#include "agglo/core/error.hpp"
#include "agglo/dem/jkr.hpp"
#include "agglo/impact/agglomerate.hpp"
#include "agglo/impact/impact_case.hpp"
#include "agglo/impact/orientation.hpp"

using namespace agglo;
using namespace agglo::impact;

namespace {

const char* kOrientations[] = {"edge_across", "edge_along", "face", "vertex"};

Config e0p9_case() { return Config::load(std::string(AGGLO_SOURCE_DIR) + "/cases/seed000_neutral_tetrahedron_e0p9.toml"); }  // no orientation key

ImpactCase oriented_case(const std::string& shape, const std::string& orientation) {
  Config cfg = e0p9_case();
  cfg.apply_override("agglomerate.shape=\"" + shape + "\"");
  cfg.apply_override("agglomerate.orientation=\"" + orientation + "\"");
  cfg.apply_override("agglomerate.charged=true");
  return parse_impact_case(cfg);
}

// Centre distance of touching neighbours: 2 r - delta0, delta0 = a0^2/(3 R) at R = r/2.
double touching_distance(const ImpactCase& c) {
  const double r = c.agglomerate.radius;
  return 2.0 * r - dem::JkrPair::make(0.5 * r, c.dem.contact.estar(), c.dem.contact.surface_energy).delta_equilibrium();
}

}  // namespace

TEST(Orientation, ContactsCentroidAndChargesKept) {
  for (std::string shape : {"tetrahedron", "square"})
    for (const char* o : kOrientations) {
      const ImpactCase c = oriented_case(shape, o);
      const dem::Particles p = build_agglomerate(c);
      ASSERT_EQ(p.size(), 4u);
      const double L = touching_distance(c);
      Vec3 centroid;
      for (std::size_t k = 0; k < 4; ++k) centroid += p.x[k] / 4.0;
      EXPECT_LT(norm(centroid), 1e-12 * L) << shape << " " << o;
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) {
          // tetrahedron: all six pairs touch; square: the ring 0-1-2-3 touches, diagonals 0-2, 1-3 at sqrt(2) L.
          const bool diagonal = shape == "square" && j - i == 2;
          const double expect = diagonal ? std::sqrt(2.0) * L : L;
          EXPECT_NEAR(norm(p.x[i] - p.x[j]), expect, 1e-12 * L) << shape << " " << o << " pair " << i << "-" << j;
        }
      const double q = c.agglomerate.charge_density * 4.0 * constants::pi * c.agglomerate.radius * c.agglomerate.radius;
      for (int k = 0; k < 4; ++k) EXPECT_EQ(p.q[k], k % 2 == 0 ? q : -q) << shape << " " << o;
    }
}

TEST(Orientation, OriginalGeometryUntouched) {
  // The default (key absent) and the shape's original name give the positions built before the key
  // existed, bit for bit: tetrahedron edge 0-1 along z at x = -h, h = L/(2 sqrt 2).
  Config cfg = e0p9_case();
  const ImpactCase c = parse_impact_case(cfg);
  EXPECT_EQ(c.agglomerate.orientation, "edge_across");
  const dem::Particles p = build_agglomerate(c);
  const double L = touching_distance(c), h = L / (2.0 * std::sqrt(2.0));
  EXPECT_EQ(p.x[0].x, -h);
  EXPECT_EQ(p.x[0].z, -L / 2);
  EXPECT_EQ(p.x[1].z, L / 2);
  EXPECT_EQ(p.x[3].y, L / 2);
  const dem::Particles same = build_agglomerate(oriented_case("tetrahedron", "edge_across"));
  for (int k = 0; k < 4; ++k) EXPECT_EQ(norm2(same.x[k] - p.x[k]), 0.0);
  EXPECT_FALSE(named_orientation("square", "edge_along").has_value());
  EXPECT_FALSE(named_orientation("tetrahedron", "").has_value());
  EXPECT_THROW(named_orientation("tetrahedron", "sideways"), std::invalid_argument);
}

TEST(Orientation, HitEdgeAcrossOrAlongTheOffset) {
  for (std::string shape : {"tetrahedron", "square"})
    for (std::string o : {"edge_across", "edge_along"}) {
      const ImpactCase c = oriented_case(shape, o);
      const dem::Particles p = build_agglomerate(c);
      const double L = touching_distance(c);
      const int a = 0, b = shape == "tetrahedron" ? 1 : 3;  // the hit edge / side
      const Vec3 e = p.x[b] - p.x[a];
      // The hit edge is the one nearest the projectile: both ends at the smallest x.
      for (int k = 0; k < 4; ++k) {
        if (k != a && k != b) {
          EXPECT_GT(p.x[k].x, p.x[a].x + 0.1 * L) << shape << " " << o;
        }
      }
      EXPECT_NEAR(p.x[a].x, p.x[b].x, 1e-12 * L);
      const double along_y = std::abs(e.y), along_z = std::abs(e.z);
      EXPECT_NEAR(o == "edge_along" ? along_y : along_z, L, 1e-12 * L) << shape << " " << o;
      EXPECT_NEAR(o == "edge_along" ? along_z : along_y, 0.0, 1e-12 * L) << shape << " " << o;
    }
}

TEST(Orientation, FaceAndVertexPositions) {
  // Tetrahedron: circumradius R_c = L sqrt(3/8); a face lies R_c/3 from the centroid.
  ImpactCase c = oriented_case("tetrahedron", "face");
  const double L = touching_distance(c), rc = L * std::sqrt(3.0 / 8.0), tol = 1e-12 * L;
  dem::Particles p = build_agglomerate(c);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.x[k].x, -rc / 3.0, tol);
  EXPECT_NEAR(norm(p.x[3] - Vec3{rc, 0.0, 0.0}), 0.0, tol);
  // The projectile starts gap_radii r_p before the nearest surface, aimed at the centroid + offset.
  const double r = c.agglomerate.radius;
  add_projectile(p, c, 0.1);
  EXPECT_NEAR(p.x[4].x, -rc / 3.0 - r - c.projectile.gap_radii * r - c.projectile.radius, tol);
  EXPECT_NEAR(p.x[4].y, c.projectile.offset_radii * r, tol);
  EXPECT_NEAR(p.x[4].z, 0.0, tol);

  p = build_agglomerate(oriented_case("tetrahedron", "vertex"));
  EXPECT_NEAR(norm(p.x[3] - Vec3{-rc, 0.0, 0.0}), 0.0, tol);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.x[k].x, rc / 3.0, tol);

  p = build_agglomerate(oriented_case("square", "face"));
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(p.x[k].x, 0.0, tol);
  p = build_agglomerate(oriented_case("square", "vertex"));
  EXPECT_NEAR(norm(p.x[0] - Vec3{-L / std::sqrt(2.0), 0.0, 0.0}), 0.0, tol);
  EXPECT_NEAR(norm(p.x[2] - Vec3{L / std::sqrt(2.0), 0.0, 0.0}), 0.0, tol);
  for (int k : {1, 3}) EXPECT_NEAR(p.x[k].x, 0.0, tol);
}

TEST(Orientation, KeyCheckedAndAbsentFromResolvedConfig) {
  Config plain = e0p9_case();
  (void)parse_impact_case(plain);
  EXPECT_EQ(plain.resolved_toml().find("orientation"), std::string::npos);

  Config bad = e0p9_case();
  bad.apply_override("agglomerate.orientation=\"corner\"");
  EXPECT_THROW(parse_impact_case(bad), ConfigError);

  Config list = Config::from_string(
      "[agglomerate]\nshape = \"list\"\norientation = \"face\"\n"
      "[[particles]]\nposition = [0.0, 0.0, 0.0]\nradius = 1e-5\n"
      "[[particles]]\nposition = [1.99e-5, 0.0, 0.0]\nradius = 1e-5\n");
  EXPECT_THROW(parse_impact_case(list), ConfigError);

  Config field = e0p9_case();
  field.apply_override("breakup.orientations=4");
  field.apply_override("electrostatics.external_field=[0.0, 0.0, 1e5]");
  EXPECT_THROW(parse_impact_case(field), ConfigError);
}
