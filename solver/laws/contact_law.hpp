#pragma once
// The contact laws the 2D NLGS solves: one parameter struct per law, fields named as LMGC90's
// TACT_BEHAV.OUT names them. spec: contact-laws.md §0 (catalogue), §3 (laws one by one).
#include <array>
#include <string_view>
#include <variant>

namespace lmgc::solver {

// contact-laws.md §3.1: inelastic quasi-shock Signorini + Coulomb.
struct IqsClb {
  double sfric;
};
// IQS with static/dynamic friction (§1.3): dfric when sliding at the beginning of the step.
struct IqsDsClb {
  double dfric, sfric;
};
// IQS relative to the gap at the first call (internal g_ref).
struct IqsClbG0 {
  double sfric;
};
// Newton restitution (normal restn, tangential restt) + Coulomb.
struct RstClb {
  double restn, restt, sfric;
};
struct RstDsClb {
  double restn, restt, dfric, sfric;
};
// Gap-Signorini: end-of-step gap >= 0 (penetration corrected in one step).
struct GapSgrClb {
  double sfric;
};
struct GapSgrDsClb {
  double dfric, sfric;
};
// Velocity-Signorini (Moreau): active only when the gap is closed.
struct VelSgrClb {
  double sfric;
};
struct VelSgrDsClb {
  double dfric, sfric;
};
// Linear spring in compression (stiffness F/gap, force per length) + Coulomb.
struct ElasticRepellClb {
  double stiffness, sfric;
};
// Mohr–Coulomb cohesion until the first break (cohen, cohet: normal/tangential cohesion).
struct IqsMohrDsClb {
  double cohen, cohet, dfric, sfric;
};
// Reversible cohesion inside a wet halo of thickness Wethk.
struct IqsWetDsClb {
  double cohen, cohet, wethk, dfric, sfric;
};
// Monerie–Acary–Cangémi cohesive zone with an IQS normal part (contact-laws.md §3.5):
// friction dfric/sfric, normal and tangential stiffnesses cn, ct, viscosity visco and fracture
// energy dupre of the damage law.
struct IqsMacCzm {
  double dfric, sfric, cn, ct, visco, dupre;
};
// Bilateral glue on both components.
struct CoupledDof {};
// A law LMGC90's 2D NLGS has no branch for (MD_JKRs, a smooth law): LMGC90 then solves the
// default problem, velocity Signorini without any gap term and Coulomb with the law's friction
// (contact-laws.md §0 "Dimension note"). Reproduced for those laws only.
struct NoNlgsBranch {
  double sfric;
};

using ContactLaw =
    std::variant<IqsClb, IqsDsClb, IqsClbG0, RstClb, RstDsClb, GapSgrClb, GapSgrDsClb, VelSgrClb, VelSgrDsClb,
                 ElasticRepellClb, IqsMohrDsClb, IqsWetDsClb, IqsMacCzm, CoupledDof, NoNlgsBranch>;

// Keyword of a law as TACT_BEHAV.DAT spells it.
std::string_view law_keyword(const ContactLaw& law);

// Number of internal variables LMGC90 stores per interaction for this law (2D).
int law_internal_count(const ContactLaw& law);

}  // namespace lmgc::solver
