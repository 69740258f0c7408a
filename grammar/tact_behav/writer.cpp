#include "grammar/tact_behav/writer.hpp"

#include <array>
#include <string_view>

#include "grammar/common/fortran_format.hpp"
#include "grammar/tact_behav/law_catalogue.hpp"
#include "grammar/tact_behav/see_table.hpp"

namespace lmgc::grammar {
namespace {

// The fixed comment block LMGC90 writes first (write_comment, 96 lines; one line starts with a
// blank instead of '!', the last is 72 blanks). docs/lmgc90-facts/datbox-inputs.md §3 "Echo TACT_BEHAV.OUT".
constexpr std::array<std::string_view, 96> kHeader = {
    "! File BEHAVIOUR                                                        ",
    "!                                                                       ",
    "! The symbol   '$'       preceeds a keyword used in scanning files.     ",
    "!                                                                       ",
    "! The symbol   'behav'   stands for the nickname of a bulk or           ",
    "! contact behaviour law, character(len=5).                              ",
    "!                                                                       ",
    "! The symbol   'lawty'   stands for the name of a bulk or               ",
    "! contact behaviour law, character(len=30).                             ",
    "!                                                                       ",
    "! The symbol   'seety'   stands for description of a candidate          ",
    "! 'cdbdy' type of body, 'cdtac' type of contactor, 'cdcol' color        ",
    "! ready to meet with the contact behaviour law 'behav' an antagonist    ",
    "! 'anbdy' type of body, 'antac' type of contactor, 'ancol' color.       ",
    "!                                                                       ",
    "! Candidate antagonist objects are considered only within some distance ",
    "! 'alert'.                                                              ",
    "!                                                                       ",
    "! STANDARD PACKAGE of contact behaviour laws                            ",
    "!                                                                       ",
    "! 123456789012345678901234567890:                                       ",
    "!                               :                                       ",
    "! contact behaviour             :                                       ",
    "!                               :                                       ",
    "! IQS_CLB                       : Inelastic quasi shock &               ",
    "!                               : Coulomb law                           ",
    "! IQS_CLB_RGR                   : Inelastic quasi shock &               ",
    "!                               : Coulomb law +  Radjai Gap Rescue      ",
    "! GAP_SGR_CLB                   : Gap Signorini condition &             ",
    "!                               : Coulomb law                           ",
    "! VEL_SGR_CLB                   : Velocity Signorini condition &        ",
    "!                               : Coulomb law                           ",
    "! IQS_DS_CLB                    : Inelastic quasi shock &               ",
    "!                               : dynamic static Coulomb law            ",
    "! GAP_SGR_DS_CLB                : Gap Signorini condition &             ",
    "!                               : dynamic static Coulomb law            ",
    "! VEL_SGR_DS_CLB                : Velocity Signorini condition &        ",
    "!                               : dynamic static Coulomb law            ",
    "! RST_CLB                       : Restitution shock law &               ",
    "!                               : Coulomb law                           ",
    "! RST_DS_CLB                    : Restitution shock law &               ",
    "!                               : dynamic static Coulomb law            ",
    "! ELASTIC_REPELL_CLB            : Repulsive reaction force proportional ",
    "!                               : to penetration gap, vanishing         ",
    "!                               : otherwise & Coulomb law               ",
    "! GAP_MOHR_DS_CLB               : Mohr-Coulomb law when cohesive, else  ",
    "!                               : gap Signorini condition &             ",
    "!                               : dynamic static Coulomb law            ",
    "! IQS_DS_WET_CLB                : rather to be written:                 ",
    "! IQS_WET_DS_CLB                : non smooth Lennard Jones attraction   ",
    "!                               : law; inelastic quasi shock stands for ",
    "!                               : unilaterality &                       ",
    "!                               : dynamic static Coulomb law            ",
    "! GAP_DS_WET_CLB                : rather to be written:                 ",
    "! GAP_WET_DS_CLB                : non smooth Lennard Jones attraction   ",
    "!                               : law; gap Signorini condition stands   ",
    "!                               : for unilaterality &                   ",
    "!                               : dynamic static Coulomb law            ",
    "! ELASTIC_REPELL_WET_CLB        : non smooth Lennard Jones attraction   ",
    "!                               : law; gap Signorini condition stands   ",
    "!                               : for unilaterality & Coulomb law       ",
    "! ELASTIC_ROD                   : linear elastic rod under traction &   ",
    "!                               : compression                           ",
    "! VOIGT_ROD                     : linear visco elastic rod under        ",
    "!                               : traction & compression                ",
    "!                               : (to be used with POINT against POINT) ",
    "! ELASTIC_WIRE                  : linear elastic wire under traction &  ",
    "!                               : inactive under compression            ",
    "!                               : (to be used with POINT against POINT) ",
    "! VOIGT_WIRE                    : linear visco lastic wire under        ",
    "!                               : traction & inactive under compression ",
    "!                               : (to be used with POINT against POINT) ",
    "! MD_JKRs                       : Modified JKR Model                    ",
    "                                : (to be used with MD + DKDK or DKJC)   ",
    "! MAC_CZM                       : Monerie-Acary-Cangemi cohesive zone   ",
    "!                               : model                                 ",
    "! MP_CZM                        : Monerie-Perales cohesive zone model   ",
    "!                               :                                       ",
    "! MP3_CZM                       : Monerie-Perales cohesive zone model   ",
    "!                               : defined by 3 cohesive parameters      ",
    "! TH_CZM                        : Tvergaard-Hutchinson cohesive zone    ",
    "!                               : model                                 ",
    "! GAP_SGR_CLB_WEAR              : Archard wear model                    ",
    "!                               : modified Signorini Coulomb Law        ",
    "!                               : (to be used with MAILx)               ",
    "! IQS_SGR_CLB_WEAR              : Cohesive wear model                   ",
    "!                               : modified Signorini Coulomb Law        ",
    "!                               : (to be used with RIGID_2D)            ",
    "! COUPLED DOF                   : to impose Un=Ut=0 in a relation       ",
    "!                               :                                       ",
    "! PERIO DOF                     : to impose a periodic relation         ",
    "!                               :   U = E.Y expressed in the local frame",
    "!                               : where E is a strain tensor (given)    ",
    "!                               :       Y the periodic vector (comp)    ",
    "!                               : (to be used with POINT against POINT) ",
    "                                                                        ",
};

constexpr std::string_view kSeeTitle = " cdbdy  cdtac  cdcol  behav  anbdy  antac  ancol       alert";

// `(2X,A5,D14.7)` for parameter `index`; a missing value prints as 0 (the AST may hold fewer
// values than the catalogue when it was not produced by the parser).
void append_value(std::string& out, const LawKind& kind, const TactLaw& law, std::size_t index) {
  append_blanks(out, 2);
  append_fortran_a(out, index < kind.parameters.size() ? kind.parameters[index] : std::string_view{}, 5);
  append_fortran_d(out, index < law.parameters.size() ? law.parameters[index].value : 0.0);
}

void append_law(std::string& out, const TactLaw& law) {
  out += "$behav  lawty\n";
  // (1X,A5,2X,A30) on the first line, 38 blanks on the following ones (docs/lmgc90-facts/datbox-inputs.md
  // §3).
  std::string first;
  append_blanks(first, 1);
  append_fortran_a(first, law.nickname.value, 5);
  append_blanks(first, 2);
  append_fortran_a(first, law.keyword.value, 30);
  const LawKind* kind = find_law_kind(law.keyword.value);
  if (kind == nullptr || kind->writes.empty()) {
    // write_empty: A38 alone (COUPLED_DOF, RIGID_WIRE, ...).
    out += first;
    out += '\n';
    return;
  }
  for (std::size_t i = 0; i < kind->writes.size(); ++i) {
    const LawField& field = kind->writes[i];
    if (i == 0)
      out += first;
    else
      append_blanks(out, 38);
    for (int slot = 0; slot < field.count; ++slot)
      append_value(out, *kind, law, static_cast<std::size_t>(field.first) + static_cast<std::size_t>(slot));
    out += '\n';
  }
}

void append_see(std::string& out, const SeeEntry& see) {
  out += "$seety\n";
  out += kSeeTitle;
  out += '\n';
  // FORMAT(1X,A5,2X,A5,2X,A5,2X,A5,2X,A5,2X,A5,2X,A5,6X,D14.7)
  const Word* words[] = {&see.candidate_body,   &see.candidate_contactor, &see.candidate_colour,
                         &see.law_nickname,     &see.antagonist_body,     &see.antagonist_contactor,
                         &see.antagonist_colour};
  for (std::size_t i = 0; i < 7; ++i) {
    append_blanks(out, i == 0 ? 1 : 2);
    append_fortran_a(out, words[i]->value, 5);
  }
  append_blanks(out, 6);
  append_fortran_d(out, see.alert.value);
  out += '\n';
  // LMGC90 stores a missing or zero global alert as 1e20 and prints it only below 1e20.
  if (see.global_alert && see.global_alert->value != 0.0 && see.global_alert->value < 1.0e20) {
    out += '+';
    append_blanks(out, 53);
    append_fortran_d(out, see.global_alert->value);
    out += '\n';
  }
  out += " \n";
}

}  // namespace

std::string write_tact_behav(const TactBehavFile& file) {
  std::string out;
  for (std::string_view line : kHeader) {
    out += line;
    out += '\n';
  }
  for (const TactLaw& law : file.laws) append_law(out, law);
  out += " \n";
  for (const SeeEntry& see : lmgc90_see_order(file.sees)) append_see(out, see);
  return out;
}

}  // namespace lmgc::grammar
