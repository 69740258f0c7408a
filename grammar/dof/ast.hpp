#pragma once
// DOF.INI / DOF.OUT.n / DOF.LAST: the state of every body's nodes at one step.
// docs/lmgc90-facts/state-and-outputs.md §1.2 (header), §1.3 (blocks); datbox-inputs.md §6 (reading rules).
#include <optional>
#include <string>
#include <vector>

#include "grammar/common/field.hpp"

namespace lmgc::grammar {

// One node of a body. Values are read at columns 35-48, 56-69, 77-90 of the node line and its
// continuation lines (3 values a line); labels (`X(1)=`, ...) are not read.
struct DofNode {
  Word node_type;       // cols 2-6: NO3xx, NO6xx, NO1xx ... (the count of values is the digit)
  Integer number;       // rigid: cols 9-13; MAILx: cols 7-13 (written I6 in 8-13)
  std::vector<Real> x;  // X(1..n): displacement (rotation for rigid); THERM: T(1..n)
  std::vector<Real> v;  // V(1..n): velocity; empty for THERM
  std::vector<Real>
      frame;  // NO6xx rigid node: a(1..3), b(1..3), g(1..3) (principal frame columns); else empty
  bool operator==(const DofNode&) const = default;
};

struct DofBody {
  Word body_type;              // RBDY2, RBDY3 or MAILx
  Integer number;              // RBDY2: cols 9-15 (I7); RBDY3: cols 9-15 list-directed; MAILx: cols 7-13
  Word model;                  // MAILx: MECAx, THERM or POROx; empty for rigid bodies
  std::vector<DofNode> nodes;  // rigid bodies: exactly one
  std::optional<DofNode> rigid_part;  // MAILx with an attached rigid body (`!rigid part` line)
  bool operator==(const DofBody&) const = default;
};

// The bodies one module writes, then its dashed `!----` line (`closed`). A module with no body
// still writes its dashed line: an empty closed section. Only the last section may be open
// (a DOF.INI written by hand need not end with a dashed line).
struct DofSection {
  std::vector<DofBody> bodies;
  bool closed = true;
  bool operator==(const DofSection&) const = default;
};

struct DofFile {
  Integer step;  // `$steps` cols 9-15
  Real time;     // `$steps` cols 35-48
  std::vector<DofSection> sections;
  bool operator==(const DofFile&) const = default;
};

}  // namespace lmgc::grammar
