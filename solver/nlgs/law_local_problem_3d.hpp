#pragma once
// The local problems of the 3D laws that are not plain Signorini–Coulomb on rr (rods, wires,
// cohesive zones; the LocalForm3D of an interaction, set by its law's `prepare`), their solve with
// the other contacts frozen, and the natural-map residual of each. docs/lmgc90-facts/contact-laws.md §3.4,
// §3.5; LMGC90 mod_nlgs_3D solve_nlgs (:3937-4060), post (:4239-4290).
#include <Eigen/Core>

#include "solver/model/contact_status.hpp"
#include "solver/model/interaction_3d.hpp"

namespace lmgc::solver {

// The reaction (t, n, s) of contact c for q = u − W r: the relative velocity with its own reaction
// removed, plus covfree (so u + covfree = q + W r). `r_previous` starts the cohesive Newton;
// `tolerance` is absolute on the natural map, as for solve_signorini_coulomb_3d. c.form must not be
// coulomb. `law_state` is the interaction's (the cohesive form's terms), here and below.
Eigen::Vector3d solve_law_form_3d(const Interaction3D& c, const LawState3D& law_state,
                                  const Eigen::Vector3d& q, const Eigen::Vector3d& r_previous,
                                  double tolerance);

// The law's status for a reaction r and auxiliary velocity uu = u + covfree: rod stick; wire stick
// in tension, vnish slack; cohesive: the Coulomb status of rr (noctc with r_n ≠ 0 counts as stick).
ContactStatus law_form_status_3d(const Interaction3D& c, const LawState3D& law_state,
                                 const Eigen::Vector3d& r, const Eigen::Vector3d& uu);

// Natural-map residual (normal first, like natural_map_3d) of the law at (r, uu = u + covfree):
// rod (0, uu_n + k r_n, r_t, r_s); wire min(−r_n, −(uu_n + k r_n)) on n and (r_t, r_s); cohesive the
// Signorini–Coulomb map of (rr, uu); glued uu.
Eigen::Vector3d law_form_residual_3d(const Interaction3D& c, const LawState3D& law_state,
                                     const Eigen::Vector3d& r, const Eigen::Vector3d& uu);

}  // namespace lmgc::solver
