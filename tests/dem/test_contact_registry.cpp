// Contact sub-models by name: the per-category names, the defaults and the declared compatibility, the
// errors for unknown names, and a model added from this file with one registration line that is then
// selectable by name and used (docs/contributing.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "agglo/core/error.hpp"
#include "agglo/dem/contact/registry.hpp"
#include "agglo/dem/dem_system.hpp"

using namespace agglo;
using namespace agglo::dem;
using namespace agglo::dem::contact;

namespace {

// Toy normal model "linear_spring": F = k delta with k = E* R [N/m], no adhesion (breaks at delta < 0),
// contact radius a = sqrt(R delta).
class LinearSpringNormal {
 public:
  static constexpr Category category = Category::normal;
  static constexpr const char* name = "linear_spring";
  explicit LinearSpringNormal(const ContactParams&) {}
  double break_separation(const JkrPair&) const { return 0.0; }
  double contact_radius(const JkrPair& jkr, double delta, double) const { return std::sqrt(jkr.R * std::max(delta, 0.0)); }
  double force(const JkrPair& jkr, double a) const { return jkr.Estar * a * a; }  // E* R delta
  double stiffness(const JkrPair& jkr, double) const { return jkr.Estar * jkr.R; }
};

// Toy rolling model "constant": a moment of fixed size opposing the relative rolling (w_i - w_j) [N m].
class ConstantRolling {
 public:
  static constexpr Category category = Category::rolling;
  static constexpr const char* name = "constant";
  static constexpr double kMoment = 1e-12;
  explicit ConstantRolling(const ContactParams&) {}
  Vec3 torque(const ContactPoint& c, const JkrPair&, ContactState&) const {
    const Vec3 w = c.w_rel - dot(c.w_rel, c.n) * c.n;
    const double len = norm(w);
    return len > 0.0 ? (-kMoment / len) * w : Vec3{};
  }
};

const bool linear_spring_registered = register_model<LinearSpringNormal>();
const bool constant_rolling_registered = register_model<ConstantRolling>();

bool has(const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); }

TEST(ContactRegistry, NamesPerCategory) {
  EXPECT_TRUE(linear_spring_registered && constant_rolling_registered);
  EXPECT_TRUE(has(names(Category::normal), "jkr"));
  EXPECT_TRUE(has(names(Category::normal), "linear_spring"));
  EXPECT_EQ(names(Category::damping), (std::vector<std::string>{"alpha", "none"}));
  EXPECT_EQ(names(Category::tangential), (std::vector<std::string>{"marshall", "ruan_li"}));
  EXPECT_EQ(names(Category::rolling), (std::vector<std::string>{"constant", "marshall", "none"}));
  EXPECT_EQ(names(Category::twisting), (std::vector<std::string>{"marshall", "none"}));
  EXPECT_THROW(register_model<ConstantRolling>(), std::logic_error);  // a name is registered once
}

// The defaults are the models of DefaultModels; what a model declares decides what it combines with.
TEST(ContactRegistry, DefaultsAndDeclaredCompatibility) {
  const ModelNames m;
  EXPECT_EQ(m.normal, "jkr");
  EXPECT_EQ(m.damping, "alpha");
  EXPECT_EQ(m.tangential, "ruan_li");
  EXPECT_EQ(m.rolling, "none");
  EXPECT_EQ(m.twisting, "none");
  EXPECT_EQ(ContactParams{}.models[Category::tangential], "ruan_li");
  ModelNames springs;
  springs.rolling = "marshall";
  ASSERT_TRUE(conflict(springs));
  EXPECT_EQ(conflict(springs)->category, Category::rolling);
  EXPECT_THROW(ContactLaw(ContactParams{}, springs), ConfigError);
  springs.tangential = "marshall";
  springs.twisting = "marshall";
  EXPECT_FALSE(conflict(springs));
  springs.rolling = "constant";  // registered here; declares no need
  springs.tangential = "ruan_li";
  springs.twisting = "none";
  EXPECT_FALSE(conflict(springs));
}

TEST(ContactRegistry, UnknownNamesAndUncombinableModels) {
  ModelNames m;
  m.tangential = "velcro";
  try {
    ContactLaw law(ContactParams{}, m);
    FAIL() << "no error for an unknown model";
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("tangential"), std::string::npos) << what;
    EXPECT_NE(what.find("\"velcro\""), std::string::npos) << what;
    EXPECT_NE(what.find("\"marshall\", \"ruan_li\""), std::string::npos) << what;
  }
  m = ModelNames{};
  m.normal = "linear_spring";
  m.rolling = "constant";  // both registered outside the built-in list
  EXPECT_THROW(ContactLaw(ContactParams{}, m), ConfigError);
}

// The toy normal model is used: a head-on undamped bounce lasts pi sqrt(m*/k) and keeps the speed,
// which the adhesive JKR model would not (it snaps in, holds on and dissipates by hysteresis).
TEST(ContactRegistry, RegisteredNormalModelIsUsed) {
  const double r = 10e-6, rho = 2500.0, v = 0.05;
  DemParams prm;
  ModelNames m;
  m.normal = "linear_spring";
  m.damping = "none";
  Particles p;
  p.add({-r - 1e-8, 0, 0}, r, rho, {v / 2, 0, 0});
  p.add({r + 1e-8, 0, 0}, r, rho, {-v / 2, 0, 0});
  const double mstar = 0.5 * p.m[0], k = prm.contact.estar() * 0.5 * r;
  const double t_contact = constants::pi * std::sqrt(mstar / k);
  prm.dt = t_contact / 2000.0;
  DemSystem sys(p, prm, m);
  EXPECT_EQ(sys.contact_law().names().normal, "linear_spring");
  long in_contact = 0;
  for (long s = 0; s < 4000 + static_cast<long>(2e-8 / v / prm.dt); ++s) {
    sys.step();
    in_contact += sys.active_contacts();
  }
  EXPECT_NEAR(in_contact * prm.dt / t_contact, 1.0, 2e-3);
  EXPECT_NEAR(sys.particles().v[1].x - sys.particles().v[0].x, v, 1e-5 * v);
  EXPECT_EQ(sys.active_contacts(), 0);
}

// The toy rolling model is used with the built-in normal model: +-M on the pair against w_i - w_j.
TEST(ContactRegistry, RegisteredRollingModelIsUsed) {
  ContactParams p;
  ModelNames m;
  m.rolling = "constant";
  const ContactLaw law(p, m);
  const auto jkr = JkrPair::make(5e-6, p.estar(), p.surface_energy);
  const double r = 10e-6, L = 2 * r - jkr.delta_equilibrium();
  PairKinematics k{{0, 0, 0}, {L, 0, 0}, {}, {}, {0, 0, 3.0}, {0, 0, -1.0}, r, r, 1e-11, 1e-11};
  ContactState s;
  const PairForce f = law.evaluate_pair(jkr, k, s, 1e-9);
  ASSERT_TRUE(s.active);
  // The spin also makes the contact slide (Ruan & Li friction, lever torque along z): subtract the same
  // evaluation without rolling resistance.
  ContactState s_base;
  const PairForce base = ContactLaw(p).evaluate_pair(jkr, k, s_base, 1e-9);
  EXPECT_NEAR(f.t_on_i.z - base.t_on_i.z, -ConstantRolling::kMoment, 1e-9 * ConstantRolling::kMoment);
  EXPECT_NEAR(f.t_on_j.z - base.t_on_j.z, ConstantRolling::kMoment, 1e-9 * ConstantRolling::kMoment);
}

}  // namespace
