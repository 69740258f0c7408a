#pragma once
// LMGC90's PI_g: `real(kind=8), parameter :: PI_g = 3.14159265358979323846` has no `d0`, so the
// literal is single precision (shared/mod_overall.f90:358). Every mass, equivalent radius and
// volume of RBDY2 and RBDY3 bodies uses it (mod_RBDY2: mass = Umas avrd² PI_g, avrd = √(m/PI_g)).

namespace lmgc::solver {

inline constexpr double lmgc_pi = static_cast<double>(3.14159265358979323846f);

}  // namespace lmgc::solver
