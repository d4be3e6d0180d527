#pragma once
// The "none" sub-models: no damping (eta_N = 0, also switching off the tangential damping that reuses
// it), no rolling and no twisting resistance. Models declaring `inactive` are skipped by the pair
// kernel (no arithmetic at all).
#include "agglo/dem/contact/sub_model.hpp"

namespace agglo::dem::contact {

struct NoDamping {
  static constexpr Category category = Category::damping;
  static constexpr const char* name = "none";
  explicit NoDamping(const ContactParams&) {}
  double coefficient(double, double) const { return 0.0; }
  static constexpr bool has_lanes = true;
  template <class T>
  T coefficient_lanes(T, T) const {
    return T{};
  }
};

struct NoRolling {
  static constexpr Category category = Category::rolling;
  static constexpr const char* name = "none";
  static constexpr bool inactive = true;
  explicit NoRolling(const ContactParams&) {}
};

struct NoTwisting {
  static constexpr Category category = Category::twisting;
  static constexpr const char* name = "none";
  static constexpr bool inactive = true;
  explicit NoTwisting(const ContactParams&) {}
};

}  // namespace agglo::dem::contact
