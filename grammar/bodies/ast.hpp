#pragma once
// BODIES.DAT as data: one struct per card, in LMGC90's vocabulary.
// docs/lmgc90-facts/datbox-inputs.md §1 (block structure, rigid and MAILx cards, echo).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "grammar/common/field.hpp"

namespace lmgc::grammar {

// A number LMGC90 writes but never reads (body, element, node and contactor numbers in
// BODIES.DAT: LMGC90 numbers by order of appearance). Kept for diagnostics, never compared.
struct Ordinal {
  std::int64_t value = 0;
  SourceSpan span;
  friend bool operator==(const Ordinal&, const Ordinal&) { return true; }
};

// `PLAIN` bulk of a rigid body (RBDY2: avrd, gyrd; RBDY3: avrd and the optional I1 I2 I3 line).
struct RigidBulk {
  Word type;  // "PLAIN"
  Ordinal number;
  Word behav;  // bulk behaviour nickname (BULK_BEHAV.DAT), columns 23-27
  Real avrd;   // radius of the equivalent disk/sphere; 0 = compute from contactors
  Real gyrd;   // RBDY2 gyration radius; 0 = compute (not read for RBDY3)
  // RBDY3 "I1 = I2 = I3 =" line; zeros when the line is absent, which LMGC90 reads the same
  // way: compute the inertia from the contactors.
  std::array<Real, 3> principal_inertia{};
  friend bool operator==(const RigidBulk&, const RigidBulk&) = default;
};

// A `model ... behav ...` line under a MAILx element.
struct ModelReference {
  Word model;  // MODELS.DAT nickname, columns 23-27
  Word behav;  // BULK_BEHAV.DAT nickname, columns 37-41
  friend bool operator==(const ModelReference&, const ModelReference&) = default;
};

// A finite element of a MAILx body: type, connectivity (node ranks), model lines.
struct Element {
  Word type;  // "Q4xxx", "T3xxx", "H8xxx", ...
  Ordinal number;
  std::vector<Integer> nodes;
  std::vector<ModelReference> models;
  friend bool operator==(const Element&, const Element&) = default;
};

// A node: type NOnxx and its n coordinates (continuation line for n > 3).
struct Node {
  Word type;  // "NO3xx"
  Ordinal number;
  std::vector<Real> coordinates;
  friend bool operator==(const Node&, const Node&) = default;
};

// CYLND / PLANx embedded frame: columns alpha, beta, gamma and the shift. Without a
// 'localframe' block LMGC90 uses the identity and no shift, which is the default here.
struct LocalFrame {
  std::array<Real, 3> alpha{Real{1.0}, Real{0.0}, Real{0.0}};
  std::array<Real, 3> beta{Real{0.0}, Real{1.0}, Real{0.0}};
  std::array<Real, 3> gamma{Real{0.0}, Real{0.0}, Real{1.0}};
  std::array<Real, 3> shift{Real{0.0}, Real{0.0}, Real{0.0}};
  friend bool operator==(const LocalFrame&, const LocalFrame&) = default;
};

// One `+XXXXX` continuation of a MAILx contactor (a further ALpxx segment or surface patch).
struct ContactorContinuation {
  std::vector<Integer> nodes;
  friend bool operator==(const ContactorContinuation&, const ContactorContinuation&) = default;
};

// A POLYF patch: its vertices and faces (face indices local to the patch).
struct PolyhedronPatch {
  std::vector<std::array<Real, 3>> vertices;
  std::vector<std::array<Integer, 3>> faces;
  friend bool operator==(const PolyhedronPatch&, const PolyhedronPatch&) = default;
};

// A contactor (`$tacty` item). Which members are used is fixed by its kind in
// contactor_catalogue.hpp: scalar parameters, offsets, vertices, faces or node references.
struct Contactor {
  Word type;  // "DISKx", "POLYG", "CLxxx", ...
  Ordinal number;
  Word color;                                 // columns 23-27
  std::vector<Real> values;                   // parameters of the first line (and the offset line)
  std::vector<Integer> nodes;                 // MAILx contactors: node ranks on the first line
  std::vector<std::array<Real, 3>> vertices;  // POLYG (third component 0), POLYR, POLYD
  std::vector<std::array<Integer, 3>> faces;  // POLYR, POLYD
  std::vector<PolyhedronPatch> patches;       // POLYF
  // CYLND, PLANx: a 'localframe' block other than the identity (at most one element; kept out
  // of line so that the other contactors do not carry 200 bytes of frame each).
  std::vector<LocalFrame> frame;
  std::vector<ContactorContinuation> continuations;  // '+ALpxx', '+CSpxx', '+ASpxx' lines
  friend bool operator==(const Contactor&, const Contactor&) = default;
};

enum class BodyType { mailx, rbdy2, rbdy3 };  // order of the echo (datbox-inputs.md §1.6)

struct Body {
  BodyType type = BodyType::rbdy2;
  SourceSpan type_span;  // where the type word was read
  Ordinal number;
  std::optional<RigidBulk> rigid_bulk;  // RBDY2 / RBDY3
  std::vector<Element> elements;        // MAILx
  std::vector<Node> nodes;
  std::vector<Contactor> contactors;
  friend bool operator==(const Body&, const Body&) = default;
};

struct BodiesFile {
  // Bodies grouped as LMGC90 numbers and echoes them: MAILx, then RBDY2, then RBDY3, each group
  // in file order (a body's number is its rank within its type).
  std::vector<Body> bodies;
  friend bool operator==(const BodiesFile&, const BodiesFile&) = default;
};

std::string_view body_type_keyword(BodyType type);
// 3 when the file has RBDY3 bodies or 3D MAILx nodes (NO3xx), else 2.
int bodies_dimension(const BodiesFile& file);

}  // namespace lmgc::grammar
