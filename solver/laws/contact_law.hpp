#pragma once
// The contact-law catalogue: one header per law (its parameters, TACT_BEHAV keyword, reader, and
// the derived Signorini–Coulomb problem it poses in 2D and/or 3D), gathered here into one table,
// the ContactLaw variant. Adding a law: its header (keyword, dimensions, parameter table, the
// operations of each dimension it has), one entry in the variant, its test.
// docs/lmgc90-facts/contact-laws.md §0 (catalogue), §2 (derived problem), §3 (laws one by one).
#include <span>
#include <string_view>
#include <variant>

#include "solver/laws/coupled_dof.hpp"
#include "solver/laws/elastic_repell_clb.hpp"
#include "solver/laws/elastic_rod.hpp"
#include "solver/laws/elastic_wire.hpp"
#include "solver/laws/gap_mohr_ds_clb.hpp"
#include "solver/laws/gap_sgr_clb.hpp"
#include "solver/laws/gap_sgr_ds_clb.hpp"
#include "solver/laws/gap_wet_ds_clb.hpp"
#include "solver/laws/iqs_clb.hpp"
#include "solver/laws/iqs_clb_g0.hpp"
#include "solver/laws/iqs_ds_clb.hpp"
#include "solver/laws/iqs_mac_czm.hpp"
#include "solver/laws/iqs_mohr_ds_clb.hpp"
#include "solver/laws/iqs_wet_ds_clb.hpp"
#include "solver/laws/law_forms.hpp"
#include "solver/laws/mac_czm.hpp"
#include "solver/laws/mal_czm.hpp"
#include "solver/laws/md_jkrs.hpp"
#include "solver/laws/rst_clb.hpp"
#include "solver/laws/rst_ds_clb.hpp"
#include "solver/laws/vel_sgr_clb.hpp"
#include "solver/laws/vel_sgr_ds_clb.hpp"

namespace lmgc::solver {

using ContactLaw =
    std::variant<IqsClb, IqsDsClb, IqsClbG0, RstClb, RstDsClb, GapSgrClb, GapSgrDsClb, VelSgrClb, VelSgrDsClb,
                 ElasticRepellClb, IqsMohrDsClb, IqsWetDsClb, IqsMacCzm, CoupledDof, NoNlgsBranch, ElasticRod,
                 ElasticWire, MacCzm, MalCzm, GapMohrDsClb, GapWetDsClb>;

// Keyword of a law as TACT_BEHAV.DAT spells it.
std::string_view law_keyword(const ContactLaw& law);

// Whether the law's cohesion acts in a wet halo and its statuses take their W form (IQS_WET_DS_CLB,
// GAP_WET_DS_CLB): a contact of such a law keeps its status when its reaction is 0.
inline bool is_wet_law(const ContactLaw& law) {
  return std::holds_alternative<IqsWetDsClb>(law) || std::holds_alternative<GapWetDsClb>(law);
}

// Number of internal variables LMGC90 stores per interaction for this law (2D).
int law_internal_count(const ContactLaw& law);

// The law of a TACT_BEHAV card: its keyword's entry of the table, each of its parameters filled from
// `values` (the card's, in the law catalogue's order: grammar::TactLaw::parameters). False for a
// keyword not in the table.
bool law_from_card(std::string_view keyword, std::span<const double> values, ContactLaw& law);

// Whether the law has a 2D form (false for the 3D-only ones: rods, wires): the law's in_2d.
bool provided_in_2d(const ContactLaw& law);
// 2D: the derived problem of the law (c.covfree, c.correction, c.WW, c.mu, c.inactive, statuses, the
// internals in c.internal), after the caller has reset them; and the end-of-step statuses and
// internal variables (in `state`, the interaction's LawState2D). A law for which keeps_law_state_2d
// is false has no internal variable: its c.internal stay 0 and `state` is not touched.
bool keeps_law_state_2d(const ContactLaw& law);
void prepare_law(const ContactLaw& law, LocalProblem2D& c, const LawStep& step);
void finish_law(const ContactLaw& law, Interaction2D& c, LawState2D& state, const LawStep& step);

// 3D: the same; prepare resets c.covfree, c.inactive, c.correction first and returns false for a
// law that has no 3D form. `state` is the interaction's LawState3D; a law for which
// keeps_law_state_3d is false never reads or writes it.
bool provided_in_3d(const ContactLaw& law);
bool keeps_law_state_3d(const ContactLaw& law);
bool prepare_law(const ContactLaw& law, Interaction3D& c, LawState3D& state, const LawStep& step);
void finish_law(const ContactLaw& law, Interaction3D& c, LawState3D& state, const LawStep& step);
// Whether the law changes its local problem at the step's convergence checks (LMGC90's
// updt_*(.false.) in solve_nlgs i_check: IQS_MAC_CZM's β), and that update in 2D and 3D, from the
// velocity u of the check's local solution. True when the contact's local problem changed.
bool updates_at_check(const ContactLaw& law);
bool update_law_at_check(const ContactLaw& law, LocalProblem2D& c, const Eigen::Vector2d& u,
                         const LawStep& step);
bool update_law_at_check(const ContactLaw& law, Interaction3D& c, LawState3D& state, const Eigen::Vector3d& u,
                         const LawStep& step);

}  // namespace lmgc::solver
