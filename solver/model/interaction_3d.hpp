#pragma once
// A 3D interaction (one contact point between a candidate and an antagonist contactor): its local
// frame (t, n, s), lever arms, Delassus block, the law's local problem and the unknowns of the
// step; and the 3D pair families. docs/lmgc90-facts/numerics.md §2-§4.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "grammar/tact_behav/contactor_pairs.hpp"
#include "solver/model/contact_status.hpp"

namespace lmgc::solver {

// 3D interaction families. Detection lists the interactions in LMGC90's sweep order of the families
// (SPSPx, SPPLx, SPPRx, SPCDx, SPDCx, PRPLx, PRPRx, PTPT3, CDCDx, CDPLx: mod_nlgs_3D :670-682), not in
// this enumeration's.
enum class PairFamily3D : std::uint8_t {
  SPSPx,
  SPPLx,
  PRPRx,
  PRPLx,
  SPCDx,
  CDCDx,
  CDPLx,
  SPDCx,
  PTPT3,
  SPPRx
};
inline constexpr int kPairFamily3DCount = 10;

// The family's name: its contact module, and the block type of its Vloc_Rloc entries.
constexpr std::string_view pair_family_name(PairFamily3D family) {
  switch (family) {
    case PairFamily3D::SPSPx:
      return "SPSPx";
    case PairFamily3D::SPPLx:
      return "SPPLx";
    case PairFamily3D::PRPRx:
      return "PRPRx";
    case PairFamily3D::PRPLx:
      return "PRPLx";
    case PairFamily3D::SPCDx:
      return "SPCDx";
    case PairFamily3D::CDCDx:
      return "CDCDx";
    case PairFamily3D::CDPLx:
      return "CDPLx";
    case PairFamily3D::SPDCx:
      return "SPDCx";
    case PairFamily3D::PTPT3:
      return "PTPT3";
    case PairFamily3D::SPPRx:
      return "SPPRx";
  }
  return "";
}

// The family of a (candidate, antagonist) contactor type pair (the contactor-pair table,
// grammar/tact_behav/contactor_pairs.hpp); false for pairs the rigid 3D solver does not detect.
inline bool pair_family_3d(const std::string& candidate, const std::string& antagonist,
                           PairFamily3D& family) {
  const grammar::ContactorPair* pair =
      grammar::find_contactor_pair(grammar::see_name(candidate), grammar::see_name(antagonist));
  if (!pair) return false;
  for (int f = 0; f < kPairFamily3DCount; ++f)
    if (pair_family_name(static_cast<PairFamily3D>(f)) == pair->interaction) {
      family = static_cast<PairFamily3D>(f);
      return true;
    }
  return false;
}

// The local problem a law poses at a contact (contact-laws.md §2-§3.5). With uu = u + covfree the
// auxiliary velocity:
//  coulomb  — Signorini–Coulomb on (rr, uu), rr = r − correction e_n;
//  rod      — r = (0, r_n, 0) with uu_n + normal_compliance r_n = 0 (bilateral spring);
//  wire     — the same, tension only: 0 ≤ −r_n ⊥ −(uu_n + normal_compliance r_n) ≥ 0;
//  cohesive — r = rr + cohesive_shift + diag(cohesive_slope) uu, Signorini–Coulomb on (rr, uu);
//  glued    — uu = 0 on all three components (bilateral).
// A coulomb contact with normal_compliance > 0 (ELASTIC_REPELL_CLB) solves it with WW = W +
// normal_compliance e_n e_nᵀ, i.e. on uu = u + covfree + normal_compliance rr_n e_n.
enum class LocalForm3D : std::uint8_t { coulomb, rod, wire, cohesive, glued };

struct Interaction3D {
  // What an NLGS sweep reads of a contact comes first, together (its first 376 bytes):
  // large granular steps are memory-bound.
  std::int32_t candidate_body = 0, antagonist_body = 0;
  bool inactive = false;
  LocalForm3D form = LocalForm3D::coulomb;
  bool correction_needs_contact = false;  // Mohr: no cohesion on a contact that opens (rr = 0)
  double mu = 0.0;
  // Cohesion impulse of the WET / Mohr laws (corln = −c h on the normal): the local problem is solved
  // for rr = r − correction·e_n ≥ 0.
  double correction = 0.0;
  double normal_compliance = 0.0;  // rod, wire, coulomb (ELASTIC_REPELL_CLB): WWnn − Wnn
  // Geometry at the detection configuration: rows t, n, s of the local frame, global axes.
  Eigen::Matrix3d frame = Eigen::Matrix3d::Zero();
  // Rows: frameᵀ (ℓ × t), frameᵀ (ℓ × n), frameᵀ (ℓ × s) of each body (ℓ = contact point − centre),
  // in body axes: the rotational part of Hᵀ (numerics.md §2).
  Eigen::Matrix3d lever_candidate = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d lever_antagonist = Eigen::Matrix3d::Zero();
  Eigen::Vector3d covfree = Eigen::Vector3d::Zero();
  Eigen::Matrix3d W = Eigen::Matrix3d::Zero();  // Delassus block (t, n, s)
  Eigen::Vector3d r = Eigen::Vector3d::Zero();  // impulse over the step (t, n, s)

  // What the warm start exchanges with the stored list (recup_rloc, store_interactions) follows r,
  // together: at 64k spheres both passes stream every interaction from memory. The law's internals
  // are in its LawState3D (below).
  PairFamily3D family = PairFamily3D::SPSPx;
  ContactStatus status = ContactStatus::nknow;
  ContactStatus status_begin = ContactStatus::nknow;
  std::int32_t candidate = 0, antagonist = 0;  // contactor ids
  // PRPLx: the candidate vertex (1-based, Vloc_Rloc's CDVER); PRPRx: 0. Warm start key of PRPLx.
  std::int32_t vertex = 0;
  // The contact point about the candidate's centre in its frame: PRPRx's warm-start key
  // (recup_rloc_PRPRx matches points closer than 1e-3).
  Eigen::Vector3d candidate_point = Eigen::Vector3d::Zero();

  std::int32_t law = 0, visibility = 0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  double gap_begin = 0.0;
  Eigen::Vector3d velocity_begin = Eigen::Vector3d::Zero();  // local (t, n, s) at t_begin
  Eigen::Vector3d u = Eigen::Vector3d::Zero();               // relative velocity at the end of the step
};
static_assert(sizeof(Interaction3D) == 504);

// What only some laws keep or read per interaction: their internal variables, the contact surface and
// reference length they use, the cohesive zone's terms. Kept beside the interaction list, index for
// index, and only in a scene with such a law (keeps_law_state_3d): in every interaction these 120
// bytes would be streamed by every pass over a large list whose law uses none of them.
struct LawState3D {
  std::array<double, 6> internal{};  // the law's internal variables (Vloc_Rloc's, warm started)
  // A law's value that the step's convergence checks may change before the end of the step stores
  // it (LMGC90's taz(1)): IQS_MAC_CZM's damage β.
  double law_working = 0.0;
  // Contact surface of the cohesive laws (get_surf_*: SPSPx π (r₁r₂)²/(r₁+r₂)², SPPLx π r², PRPRx the
  // overlap area shared by the pair's points, PRPLx 0 as LMGC90 has it).
  double surface = 0.0;
  // PTPT3: the link's length in the reference configuration (nonuc0, the rods' and wires' gapREF).
  double reference_gap = 0.0;
  Eigen::Vector3d cohesive_slope = Eigen::Vector3d::Zero();  // cohesive: (k_t, k_n, k_t)
  Eigen::Vector3d cohesive_shift = Eigen::Vector3d::Zero();  // cohesive: (radh_t, 0, radh_s)
};

// A contact point as detection finds it: the pair, its visibility row, the local frame, the point
// and gap. The interaction (levers, Delassus block, start velocity) is built from it once detection's
// points are in sweep order, so that 504-byte records are written once and never moved.
struct DetectedPoint3D {
  PairFamily3D family = PairFamily3D::SPSPx;   // PTPT3: each lever reaches its contactor's centre
  std::int32_t candidate = 0, antagonist = 0;  // contactor ids
  std::int32_t visibility = 0, vertex = 0;
  Eigen::Matrix3d frame = Eigen::Matrix3d::Zero();  // rows t, n, s
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d image = Eigen::Vector3d::Zero();  // the antagonist's periodic shift
  double gap = 0.0, surface = 0.0, reference_gap = 0.0;
};

// What the next step's warm start (recup_rloc) reads of an interaction: LMGC90's verlet list entry.
// Kept apart from Interaction3D (504 bytes) because the whole list is stored every step.
struct StoredInteraction3D {
  PairFamily3D family = PairFamily3D::SPSPx;
  ContactStatus status = ContactStatus::nknow;
  // Written as zeros where the compiler would leave padding: the exact restart state copies records
  // byte for byte, and two runs' files must compare equal.
  std::array<std::uint8_t, 2> unused{};
  std::int32_t candidate = 0, antagonist = 0, vertex = 0;  // the key
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  Eigen::Vector3d candidate_point = Eigen::Vector3d::Zero();  // PRPRx points of a pair match by place
  std::array<double, 6> internal{};

  StoredInteraction3D() = default;
  // `law_state`: the interaction's, or null in a scene without law state (internals stored as 0).
  StoredInteraction3D(const Interaction3D& c, const LawState3D* law_state)
      : family(c.family),
        status(c.status),
        candidate(c.candidate),
        antagonist(c.antagonist),
        vertex(c.vertex),
        r(c.r),
        candidate_point(c.candidate_point) {
    if (law_state) internal = law_state->internal;
  }
};

static_assert(sizeof(StoredInteraction3D) == 112,
              "StoredInteraction3D has padding the exact state would copy");

}  // namespace lmgc::solver
