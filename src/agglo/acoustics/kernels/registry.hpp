#pragma once
// The registered kernel mechanisms, one file each, selected by name (mechanism_names() in
// settings.hpp). The order of this list is the summation order of beta and of its bounds.
#include "agglo/acoustics/kernels/acoustic_wake.hpp"
#include "agglo/acoustics/kernels/additive.hpp"
#include "agglo/acoustics/kernels/brownian.hpp"
#include "agglo/acoustics/kernels/brownian_fuchs.hpp"
#include "agglo/acoustics/kernels/brownian_partmc.hpp"
#include "agglo/acoustics/kernels/constant.hpp"
#include "agglo/acoustics/kernels/mechanism_set.hpp"
#include "agglo/acoustics/kernels/orthokinetic.hpp"
#include "agglo/acoustics/kernels/radiation_pressure.hpp"

namespace agglo::acoustics {

using KernelMechanisms = MechanismSet<
    Orthokinetic,
    AcousticWake,
    RadiationPressure,
    Brownian,
    BrownianFuchs,
    ConstantKernel,
    AdditiveKernel,
    BrownianPartmc>;

}  // namespace agglo::acoustics
