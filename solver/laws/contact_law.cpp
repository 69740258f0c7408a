#include "solver/laws/contact_law.hpp"

namespace lmgc::solver {
namespace {
template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;
}  // namespace

std::string_view law_keyword(const ContactLaw& law) {
  return std::visit(Overloaded{
                        [](const IqsClb&) { return std::string_view("IQS_CLB"); },
                        [](const IqsDsClb&) { return std::string_view("IQS_DS_CLB"); },
                        [](const IqsClbG0&) { return std::string_view("IQS_CLB_g0"); },
                        [](const RstClb&) { return std::string_view("RST_CLB"); },
                        [](const RstDsClb&) { return std::string_view("RST_DS_CLB"); },
                        [](const GapSgrClb&) { return std::string_view("GAP_SGR_CLB"); },
                        [](const GapSgrDsClb&) { return std::string_view("GAP_SGR_DS_CLB"); },
                        [](const VelSgrClb&) { return std::string_view("VEL_SGR_CLB"); },
                        [](const VelSgrDsClb&) { return std::string_view("VEL_SGR_DS_CLB"); },
                        [](const ElasticRepellClb&) { return std::string_view("ELASTIC_REPELL_CLB"); },
                        [](const IqsMohrDsClb&) { return std::string_view("IQS_MOHR_DS_CLB"); },
                        [](const IqsWetDsClb&) { return std::string_view("IQS_WET_DS_CLB"); },
                        [](const IqsMacCzm&) { return std::string_view("IQS_MAC_CZM"); },
                        [](const CoupledDof&) { return std::string_view("COUPLED_DOF"); },
                        [](const NoNlgsBranch&) { return std::string_view("MD_JKRs"); },
                    },
                    law);
}

int law_internal_count(const ContactLaw& law) {
  // state-and-outputs.md §1.4.4: g_ref for the _g0 laws, taille_ele for the GAP/VEL_SGR family.
  return std::visit(Overloaded{
                        [](const IqsClbG0&) { return 1; },
                        [](const GapSgrClb&) { return 1; },
                        [](const GapSgrDsClb&) { return 1; },
                        [](const VelSgrClb&) { return 1; },
                        [](const VelSgrDsClb&) { return 1; },
                        [](const IqsMacCzm&) { return 5; },
                        [](const auto&) { return 0; },
                    },
                    law);
}

}  // namespace lmgc::solver
