#pragma once
// What every contact law file builds on: the step data a law sees, the table of a law's
// parameters, and the forms shared by several laws (contact-laws.md §1.3, §2). A law is one header
// of this folder: its parameter struct (keyword, the dimensions it has, internal-variable count,
// parameter table) and its `prepare` (derived Signorini–Coulomb problem, once per step) and
// `finish` (statuses and internal variables at the end of the step) for the interactions of each
// dimension it has. contact_law.hpp gathers them into the ContactLaw table.
#include <array>
#include <string_view>

#include "solver/model/contact_status.hpp"
#include "solver/model/interaction_2d.hpp"
#include "solver/model/interaction_3d.hpp"

namespace lmgc::solver {

// One parameter of a law: the name under which the law catalogue lists it (TACT_BEHAV.OUT's,
// "sfric", "restn", ...) and the member it fills. Each law lists its parameters in a table
// `parameters`; law_from_card fills them from the card, and a name the catalogue does not have for
// the law's keyword is refused there (and by the test ContactLawTable.EveryParameterIsOnItsCatalogueCard),
// never read as 0.
template <class Law>
struct LawParameter {
  std::string_view name;
  double Law::*member;
};

struct LawStep {
  double h = 0.0;           // time step [s]
  double time = 0.0;        // end of the step [s]
  bool first_step = false;  // Nstep = 1 (IQS_MOHR_DS_CLB's Mstck, the CZMs' internals reset)
  // LMGC90's first NLGS preparation of the run that has interactions (`.not. is_initialized`):
  // IQS_CLB_g0's reference gap, the CZMs' Cnnow start.
  bool first_preparation = false;
};

inline double positive(double x) {
  return x > 0.0 ? x : 0.0;
}

// §1.3: dynamic friction when the contact was sliding at the beginning of the step.
inline double static_dynamic(double dfric, double sfric, ContactStatus begin) {
  return is_sliding(begin) ? dfric : sfric;
}

// "IQS form": the bodies may close an open gap within the step, no push-out when penetrated.
template <class Interaction>
void iqs_form(Interaction& c, double h) {
  c.covfree(1) = positive(c.gap_begin) / h;
}
// "GAP form": the end-of-step gap must be >= 0 (penetrations corrected in one step).
template <class Interaction>
void gap_form(Interaction& c, double h) {
  c.covfree(1) = c.gap_begin / h;
}
// Newton restitution: covfree = (restt v_t, restn v_n[, restt v_s]) of the velocity at t_begin;
// inactive while the gap is open.
template <class Interaction>
void restitution_form(Interaction& c, double restn, double restt) {
  if (c.gap_begin > 0.0) {
    c.inactive = true;
    return;
  }
  c.covfree = restt * c.velocity_begin;
  c.covfree(1) = restn * c.velocity_begin(1);
}

// 2D cohesion c (force) acting through the normal (contact-laws.md §3.2): the local problem is
// solved for rr_n = r_n + c h >= 0, i.e. covfree −= c h W e_n and r = rr + correction.
inline void add_cohesion(LocalProblem2D& c, double cohesion, double h) {
  c.covfree(0) -= cohesion * h * c.W(0, 1);
  c.covfree(1) -= cohesion * h * c.WW(1, 1);
  c.correction(1) = -cohesion * h;
}

// Rods and wires (contact-laws.md §3.4): a spring of stiffness F/str (force per unit strain) and
// prestrain prstr on a link of reference length gapREF. The impulse r_n = −h F/str ε_end, with
// ε_end = (γ_begin + h u_n)/gapREF − 1 − prstr, is uu_n + (gapREF/(F/str h²)) r_n = 0 for
// uu_n = u_n + covfree_n, covfree_n = (γ_begin − (1 + prstr) gapREF)/h (mod_nlgs_3D prep :1700-1728).
// No link without a reference length (LMGC90 stops there; build_scene_3d refuses rods and wires on
// pairs other than PTPT3, the only 3D family that sets it).
inline void spring_form(Interaction3D& c, LawState3D& s, double force_per_strain, double prestrain, double h,
                        LocalForm3D form) {
  s.internal[0] = s.reference_gap;
  if (s.reference_gap <= 1e-18 || force_per_strain <= 0.0) {
    c.inactive = true;
    return;
  }
  c.form = form;
  c.normal_compliance = s.reference_gap / (force_per_strain * h * h);
  c.covfree(1) = (c.gap_begin - (1.0 + prestrain) * s.reference_gap) / h;
  c.mu = 0.0;
}

// Laws without end-of-step work.
template <class Law, class Interaction>
void finish(const Law&, Interaction&, const LawStep&) {}

}  // namespace lmgc::solver
