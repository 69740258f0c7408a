#pragma once
// A 2D interaction (one contact point between a candidate and an antagonist contactor), with
// its local frame, its Delassus block and the unknowns of the step. docs/lmgc90-facts/numerics.md §2-§4.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string_view>

#include "solver/model/contact_status.hpp"

namespace lmgc::solver {

// 2D interaction families, in the order LMGC90 sweeps them (numerics.md §4 step 2: DKDKx, DKKDx,
// DKJCx, DKPLx, PTPT2, PLPLx, PLJCx, CLALp, CLJCx, P2P2L, PLALp, DKALp, DKDKL; mod_nlgs prep_nlgs). The first
// seven join rigid bodies (solver/detection/detection_2d.hpp); the others have a side on a mesh
// (mesh_contact_2d.hpp).
enum class PairFamily2D : std::uint8_t {
  DKDKx,
  DKKDx,
  DKJCx,
  DKPLx,
  PTPT2,
  PLPLx,
  PLJCx,
  CLALp,
  CLJCx,
  P2P2L,
  PLALp,
  DKALp,
  DKDKL
};

// The family's name: its interaction module, as the contactor-pair table and Vloc_Rloc files name it.
constexpr std::string_view pair_family_name(PairFamily2D family) {
  switch (family) {
    case PairFamily2D::DKDKx:
      return "DKDKx";
    case PairFamily2D::DKKDx:
      return "DKKDx";
    case PairFamily2D::DKJCx:
      return "DKJCx";
    case PairFamily2D::DKPLx:
      return "DKPLx";
    case PairFamily2D::PTPT2:
      return "PTPT2";
    case PairFamily2D::PLPLx:
      return "PLPLx";
    case PairFamily2D::PLJCx:
      return "PLJCx";
    case PairFamily2D::CLALp:
      return "CLALp";
    case PairFamily2D::CLJCx:
      return "CLJCx";
    case PairFamily2D::P2P2L:
      return "P2P2L";
    case PairFamily2D::PLALp:
      return "PLALp";
    case PairFamily2D::DKALp:
      return "DKALp";
    case PairFamily2D::DKDKL:
      return "DKDKL";
  }
  return "";
}
inline constexpr int kPairFamily2DCount = 13;
static_assert(static_cast<int>(PairFamily2D::DKDKL) + 1 == kPairFamily2DCount);
// The families between rigid bodies: PairFamily2D's first seven.
inline constexpr int kRigidPairFamily2DCount = 7;
static_assert(static_cast<int>(PairFamily2D::PLJCx) + 1 == kRigidPairFamily2DCount);

// Whether the candidate (side 0) or the antagonist (side 1) of a family is a mesh contactor
// (CLxxx, ALpxx, PT2DL, DISKL: Scene2D::mesh_contactors) rather than a rigid one (Scene2D::contactors).
constexpr bool side_on_mesh(PairFamily2D family, int side) {
  switch (family) {
    case PairFamily2D::CLALp:
    case PairFamily2D::P2P2L:
      return true;
    case PairFamily2D::CLJCx:
      return side == 0;
    case PairFamily2D::PLALp:
    case PairFamily2D::DKALp:
    case PairFamily2D::DKDKL:
      return side == 1;
    default:
      return false;
  }
}
constexpr bool is_mesh_family(PairFamily2D family) {
  return static_cast<int>(family) >= kRigidPairFamily2DCount;
}

// 64-byte aligned, 192 bytes in three cache lines: the per-step passes over a large list (detection,
// warm start, NLGS set-up and end) move whole lines. The fields are grouped by the passes that read
// them: the warm start (recup_rloc) touches only the first line of this step's and of the stored
// list's records (key, reaction, statuses, point), the NLGS set-up reads the geometry of lines 1-2.
// The law's local problem is not kept here (LocalProblem2D below), nor its internal variables
// (LawState2D, kept beside the list only where a law has some).
struct alignas(64) Interaction2D {
  // Line 0: the key, the reaction and the statuses.
  PairFamily2D family = PairFamily2D::DKDKx;
  ContactStatus status = ContactStatus::nknow;
  ContactStatus status_begin = ContactStatus::nknow;
  // Cohesive zone laws: impulse r_coh = (shift_t, 0) + diag(slope) · uu, uu the auxiliary velocity.
  bool cohesive = false;
  bool inactive = false;  // forecast inactive ("noact"): r = 0, skipped by the sweeps
  // Zeros where the compiler would leave padding: the exact restart state copies records byte for
  // byte, and two runs' files must compare equal.
  std::array<std::uint8_t, 3> unused{};
  std::int32_t candidate = 0;  // contactor ids (Scene2D::contactors)
  std::int32_t antagonist = 0;
  std::int32_t candidate_vertex = 0;  // PLPLx/PLJCx: vertex of the candidate polygon (1-based, 0 none)
  std::int32_t candidate_body = 0;
  std::int32_t antagonist_body = 0;
  std::int32_t law = 0;  // index into Scene2D::laws
  // Step unknowns: impulse (t, n) over the step and relative velocity at the end of the step.
  Eigen::Vector2d r = Eigen::Vector2d::Zero();
  Eigen::Vector2d point = Eigen::Vector2d::Zero();  // contact point

  // Lines 1-2: geometry at the detection configuration (θ-scheme "TT" configuration), and the rest
  // of the pair's description.
  Eigen::Vector2d normal = Eigen::Vector2d::Zero();  // from antagonist to candidate
  double gap_begin = 0.0;                            // signed distance at detection [m]
  double length = 1.0;                               // contact length used by cohesive laws
  double cohesive_shift_t = 0.0;                     // cohesive zone laws: r_coh's tangential shift
  double mu = 0.0;                                   // friction coefficient of the law's local problem
  // Lever-arm products ℓ×t and ℓ×n of each body (H rows of the rotational dof).
  Eigen::Vector2d lever_candidate = Eigen::Vector2d::Zero();
  Eigen::Vector2d lever_antagonist = Eigen::Vector2d::Zero();
  Eigen::Vector2d velocity_begin = Eigen::Vector2d::Zero();  // local (t, n) relative velocity at t_begin
  Eigen::Vector2d u = Eigen::Vector2d::Zero();
  std::int32_t antagonist_segment = 0;       // PLPLx: segment of the antagonist polygon
  std::int32_t visibility = 0;               // index into Scene2D::visibility
  std::int32_t periodic_shift = 0;           // antagonist shifted by this many periods in x
  std::array<std::uint8_t, 4> unused_end{};  // the last of the record's 192 bytes (zeros, as above)

  // The tangent (n_y, -n_x): computed, not kept (16 bytes of every record of every pass).
  Eigen::Vector2d tangent() const { return Eigen::Vector2d(normal.y(), -normal.x()); }
};
static_assert(sizeof(Interaction2D) == 192);

// An interaction with the local problem of its law (contact-laws.md §2): Delassus block, modified
// block, shift, correction. What a 2D law's prepare works on; the NLGS set-up builds it for one
// contact at a time and keeps the interaction's part. Kept in the list, these 96 bytes (and the
// internals) would take it from three to six cache lines per interaction, which detection wrote and
// the set-up wrote again.
struct LocalProblem2D : Interaction2D {
  Eigen::Matrix2d W = Eigen::Matrix2d::Zero();
  Eigen::Matrix2d WW = Eigen::Matrix2d::Zero();
  Eigen::Vector2d covfree = Eigen::Vector2d::Zero();
  Eigen::Vector2d correction = Eigen::Vector2d::Zero();  // corr added to the auxiliary reaction
  Eigen::Vector2d cohesive_slope = Eigen::Vector2d::Zero();
  // The contact's internal variables (its LawState2D's, or 0 where the scene keeps none): the set-up
  // copies them in and back.
  std::array<double, 6> internal{};
};

// A 2D law's internal variables (contact-laws.md, state-and-outputs §1.4.4), warm started and
// written to Vloc_Rloc. Kept beside the interaction list, index for index, only in a scene with a
// law that has some (keeps_law_state_2d): in every record they would be 48 bytes that each pass over
// a large list streams, for laws (IQS_CLB, ...) that have none.
struct LawState2D {
  std::array<double, 6> internal{};
};

}  // namespace lmgc::solver
