#pragma once
// PTPT3_NETWORK.DAT: the PT3Dx links of a 3D case, listed instead of detected (LMGC90's
// PTPT3_LoadNetwork). One list-directed record per link:
//   icdtac iantac xper yper iloop nonuc0              (plain form)
//   icdtac iantac xper yper iloop surf nonuc0 mass    (with PTPT3_LoadParams)
// icdtac, iantac: ranks of the two points among the case's PT3Dx contactors (1-based, body order);
// xper, yper: periods the link crosses; iloop = 1: the period shift moves the candidate, else the
// antagonist. LMGC90 source: contact_3D/mod_PTPT3.f90 compute_box (:420-490), compute_contact.
#include <optional>
#include <vector>

#include "grammar/common/field.hpp"

namespace lmgc::grammar {

struct Ptpt3Link {
  Integer candidate;            // icdtac
  Integer antagonist;           // iantac
  Integer x_periods;            // xper
  Integer y_periods;            // yper
  Integer loop;                 // iloop (1: the candidate is shifted)
  Real reference_length;        // nonuc0 [m]
  std::optional<Real> surface;  // surf, with parameters only
  std::optional<Real> mass;     // mass, with parameters only
  bool operator==(const Ptpt3Link&) const = default;
};

struct Ptpt3NetworkFile {
  bool with_parameters = false;  // eight items per record (surf nonuc0 mass) instead of six
  std::vector<Ptpt3Link> links;  // in file order
  bool operator==(const Ptpt3NetworkFile&) const = default;
};

}  // namespace lmgc::grammar
