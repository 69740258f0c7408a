// spec: contact-laws.md §2 (derived Signorini–Coulomb), §3.1-3.4 (laws one by one).
#include "solver/laws/law_local_problem_2d.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace lmgc::solver {
namespace {

using Eigen::Vector2d;

bool is_wet_law(const ContactLaw& law) {
  return std::holds_alternative<IqsWetDsClb>(law);
}

}  // namespace

void prepare_local_problem_2d(const ContactLaw& law, LocalProblem2D& c, const LawStep& step) {
  c.WW = c.W;
  c.covfree.setZero();
  c.correction.setZero();
  c.cohesive_slope.setZero();
  c.inactive = false;
  c.mu = 0.0;
  prepare_law(law, c, step);  // each law's own file (solver/laws/*.hpp)
  // Guard of the tangential term for degenerate blocks (§2).
  if (c.WW(0, 0) <= 1e-6 * c.WW(1, 1)) c.WW(0, 0) = 1e-6 * c.WW(1, 1);
}

LocalSolution2D solve_local_problem_2d(const ContactLaw& law, const LocalProblem2D& c,
                                       const Vector2d& ufree_loc) {
  const Vector2d vv = ufree_loc + c.covfree;
  LocalSolution2D s;
  if (c.inactive) return s;
  if (std::holds_alternative<CoupledDof>(law)) {
    // Bilateral glue: u = 0 on both components.
    s.r = -c.WW.inverse() * vv;
    s.status = ContactStatus::stick;
    return s;
  }
  s = solve_signorini_coulomb_2d(c.WW, vv, c.mu);
  s.r += c.correction;
  if (is_wet_law(law) && !(c.correction.array() == 0.0).all()) s.status = wet_status(s.status);
  return s;
}

double local_residual_squared_2d(const ContactLaw& law, const LocalProblem2D& c, const Vector2d& r,
                                 const Vector2d& ufree_loc) {
  if (c.inactive) return r.squaredNorm();
  const Vector2d rr = r - c.correction;
  const Vector2d uu = ufree_loc + c.covfree + c.WW * rr;
  if (std::holds_alternative<CoupledDof>(law)) return uu.squaredNorm();
  return natural_map_residual_squared_2d(rr, uu, c.mu);
}

void finish_step_2d(const ContactLaw& law, Interaction2D& c, double h, double time) {
  finish_law(law, c, LawStep{h, time, false});
}

}  // namespace lmgc::solver
