#pragma once
// The MAILx bodies of a case as meshes (solver/fem/linear_body.hpp): elements from BODIES.DAT with
// the finite element of their MODELS.DAT model, materials from the ELAS laws of BULK_BEHAV.DAT
// (Umas, EYng, EPss) — linear elasticity in small strain, MatLib's neo-Hookean material in large
// strain (total Lagrangian, fem/large_strain.hpp) — lumped or consistent mass from the model's
// 'mstrg'. What lmgc does not run yet (the updated Lagrangian form, another material, an
// anisotropic law, a thermal model, an element outside the catalogue) is refused with L4003 at the
// model's line: never replaced by another model; so is a contactor other than CLxxx and ALpxx.
// docs/lmgc90-facts/mailx-2d.md §1-§3, mailx-2d-large-strain.md §1-§2.
#include <cstdint>
#include <string>
#include <vector>

#include "case_folder/case_files.hpp"
#include "grammar/common/diagnostic.hpp"
#include "solver/fem/linear_body.hpp"

namespace lmgc::solver {

// A contactor of a mesh (BODIES.DAT '$tacty' of a MAILx body): a CLxxx candidate point on the edge
// (a, b) at apab from a, or an ALpxx polyline of nodes whose consecutive pairs are its segments
// ('+ALpxx' continuation lines add segments). docs/lmgc90-facts/mailx-2d-contact.md §1-§2.
// CLxxx: a candidate point; ALpxx: a polyline; PT2DL: a point of either side (P2P2L); DISKL: the
// disk through an arc on an edge (DKDKL's antagonist).
enum class MeshContactorShape : std::uint8_t { candidate_point, polyline, point, disk };

struct MeshContactor {
  MeshContactorShape shape = MeshContactorShape::candidate_point;
  std::string type;  // "CLxxx", "ALpxx", "PT2DL", "DISKL"
  std::string color;
  std::int32_t mesh = 0;    // index into MeshBodies::bodies (the MAILx body's rank − 1)
  std::int32_t rank = 1;    // rank within its body's $tacty list, every type counted (Vloc_Rloc 'numbr')
  std::int32_t serial = 1;  // rank among the case's contactors of its type (LMGC90's module list)
  std::vector<std::int32_t> nodes;  // 0-based; CLxxx, PT2DL, DISKL: (a, b); ALpxx: the polyline's nodes
  double apab = 0.0;                // CLxxx, PT2DL, DISKL: the point (1 − apab) a + apab b
  // DISKL (mod_DISKL): the arc's sagitta h (bdyr) and half chord c (brpm) over its point of the edge;
  // the disk's radius r = (h² + c²)/(2h), its centre r − h behind the point, on the edge's left.
  double arc_height = 0.0, arc_half_chord = 0.0;
  double disk_radius() const {
    return (arc_height * arc_height + arc_half_chord * arc_half_chord) / (2.0 * arc_height);
  }
  std::size_t segments() const { return nodes.size() < 2 ? 0 : nodes.size() - 1; }
};

struct MeshBodies {
  std::vector<fem::MeshBody> bodies;
  std::vector<MeshContactor> contactors;
  // The model options that change outputs, per body: MatLib's GPV layout ('isext MatL_').
  std::vector<bool> matlib;
};

// The MAILx contactors lmgc runs in 2D: CLxxx, ALpxx, PT2DL and DISKL.
bool runs_mesh_contactor_2d(std::string_view type);

// `hypothesis`: SetDimension(2, mhyp)'s (plane strain 1, plane stress 2, axisymmetric 3), or 3D.
bool build_mesh_bodies(const case_folder::CaseFiles& files, fem::Hypothesis hypothesis, MeshBodies& out,
                       grammar::DiagnosticSink& sink);

}  // namespace lmgc::solver
