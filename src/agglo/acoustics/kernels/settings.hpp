#pragma once
// Kernel selection of a case ([kernels] keys): the model, and for the acoustic model which of its
// mechanisms are summed (docs/model.md §C.3). Turned into mechanism names by mechanism_names().
#include <string>
#include <vector>

namespace agglo::acoustics {

enum class KernelModel { acoustic, constant, additive, brownian_fuchs, brownian_partmc };
enum class BrownianForm { continuum_slip, fuchs };
KernelModel kernel_model_from_name(const std::string& name);
const char* kernel_model_name(KernelModel m);

struct KernelSettings {
  KernelModel model = KernelModel::acoustic;
  bool orthokinetic = true;        // beta_OI+GS
  bool acoustic_wake = true;       // beta_AWE
  bool radiation_pressure = true;  // beta_MRPE
  bool brownian = true;            // beta_BD
  BrownianForm brownian_form = BrownianForm::continuum_slip;
  double collision_efficiency = 1.0;  // multiplies beta_OI+GS
  double constant_coefficient = 0.0;  // K0 [m^3/s]
  double additive_coefficient = 0.0;  // B [1/s]
  bool exclude_same_population = false;  // test switch: only pairs of different populations collide
};

// Names of the registered mechanisms (kernels/registry.hpp) the settings switch on:
// acoustic -> the enabled ones of orthokinetic, acoustic_wake, radiation_pressure, brownian;
// constant, additive, brownian_fuchs, brownian_partmc -> that one mechanism.
std::vector<std::string> mechanism_names(const KernelSettings& s);

}  // namespace agglo::acoustics
