// BODIES.OUT writer. docs/lmgc90-facts/datbox-inputs.md §1.6 (order, header, separators), §1.3-1.5 (formats).
#include "grammar/bodies/writer.hpp"

#include "grammar/bodies/contactor_catalogue.hpp"
#include "grammar/common/fortran_format.hpp"

namespace lmgc::grammar {
namespace {

// The fixed comment block LMGC90 writes at the top of BODIES.OUT (mod_overall, 19 lines).
constexpr std::string_view kHeader =
    "! File BODIES                                                           \n"
    "!                                                                       \n"
    "! The symbol   '$'      preceeds a keyword used in scanning files.    \n"
    "!                                                                       \n"
    "! the symbol   'bdyty'  stands for 'body type data'.                \n"
    "! These data are distributed according to some species.                 \n"
    "!                                                                       \n"
    "! the specy    'blmty'  stands for 'bulk element type data',        \n"
    "! i.e. part or total bulk geometric description,                        \n"
    "! and bulk behaviour laws;                                              \n"
    "!                                                                       \n"
    "! the specy    'nodty'  stands for 'node type data',                \n"
    "! i.e. degrees of freedom data;                                         \n"
    "!                                                                       \n"
    "! the specy    'tacty'  stands for 'contactor type data';           \n"
    "!                                                                       \n"
    "! the keyword  '$$$$$$' ends a body record.                           \n"
    "!                                                                       \n"
    "                                                                      \n";

constexpr std::string_view kDashes =
    "!-----------------------------------------------------------------------\n";

// (2X,A5,D14.7) label/value pairs after `lead` blanks: the common value layout (§1.3).
void append_pairs(std::string& out, const std::string_view* labels, const Real* values, int count) {
  for (int i = 0; i < count; ++i) {
    append_blanks(out, 2);
    append_fortran_a(out, labels[i], 5);
    append_fortran_d(out, values[i].value);
  }
}

// Continuation line: 27 blanks then pairs (format 131/132).
void append_continuation(std::string& out, const std::string_view* labels, const Real* values, int count) {
  append_blanks(out, 27);
  append_pairs(out, labels, values, count);
  out += '\n';
}

// (1X,A5,2X,I5,2X,A5,2X,A5): the common head of a contactor line (§1.4).
void append_contactor_head(std::string& out, char first, std::string_view type, std::int64_t rank,
                           std::string_view color, bool with_color = true) {
  out += first;
  append_fortran_a(out, type, 5);
  append_blanks(out, 2);
  append_fortran_i(out, rank, 5);
  append_blanks(out, 2);
  append_fortran_a(out, with_color ? "color" : "", 5);
  append_blanks(out, 2);
  append_fortran_a(out, with_color ? color : "", 5);
}

// (2X,A5,I5) node-rank pairs of MAILx contactors.
void append_node_ranks(std::string& out, const std::vector<Integer>& nodes, std::size_t first,
                       std::size_t count) {
  static constexpr std::string_view kLabels[] = {
      "noda=", "nodb=", "nodc=", "nodd=", "node=", "nodf=", "nodg=", "nodh="};
  for (std::size_t i = 0; i < count && first + i < nodes.size(); ++i) {
    append_blanks(out, 2);
    append_fortran_a(out, kLabels[i % 8], 5);
    append_fortran_i(out, nodes[first + i].value, 5);
  }
}

void append_polyhedron(std::string& out, std::int64_t vertex_count, std::int64_t face_count) {
  append_blanks(out, 2);
  out += "nb_vertex=";
  append_fortran_i(out, vertex_count, 7);
  append_blanks(out, 4);
  out += "nb_faces=";
  append_fortran_i(out, face_count, 7);
  out += '\n';
}

void append_vertices(std::string& out, const ContactorKind& kind,
                     const std::vector<std::array<Real, 3>>& vertices) {
  for (const auto& v : vertices)
    append_continuation(out, kind.offset_labels.data(), v.data(), kind.dimension);
}

// Face lines: 27 blanks then 3 × (2X,A5,I7,7X) (format 132 of the POLYR writer); the final 7X
// writes nothing — gfortran emits no trailing blanks for X at the end of a record (reference
// BODIES.OUT of Beam_ClusterPR and 100_PR_PerioBox).
void append_faces(std::string& out, const std::vector<std::array<Integer, 3>>& faces) {
  static constexpr std::string_view kLabels[] = {"ver1=", "ver2=", "ver3="};
  for (const auto& f : faces) {
    append_blanks(out, 27);
    for (int k = 0; k < 3; ++k) {
      append_blanks(out, 2);
      out += kLabels[k];
      append_fortran_i(out, f[static_cast<std::size_t>(k)].value, 7);
      if (k < 2) append_blanks(out, 7);
    }
    out += '\n';
  }
}

void append_contactor(std::string& out, const Contactor& c, std::int64_t rank) {
  const ContactorKind* kind = find_contactor_kind(c.type.value);
  if (!kind) return;  // the parser keeps only known kinds
  append_contactor_head(out, ' ', c.type.value, rank, c.color.value);
  switch (kind->layout) {
    case ContactorLayout::values:
      append_pairs(out, kind->labels.data(), c.values.data(),
                   std::min<int>(kind->value_count, static_cast<int>(c.values.size())));
      out += '\n';
      break;
    case ContactorLayout::values_offset:
      append_pairs(out, kind->labels.data(), c.values.data(), kind->value_count);
      out += '\n';
      append_continuation(out, kind->offset_labels.data(), c.values.data() + kind->value_count,
                          kind->offset_count);
      break;
    case ContactorLayout::values_frame: {
      append_pairs(out, kind->labels.data(), c.values.data(), kind->value_count);
      out += '\n';
      // LMGC90 always echoes the frame block (identity and no shift when none was given).
      const LocalFrame frame = c.frame.empty() ? LocalFrame{} : c.frame.front();
      append_blanks(out, 29);
      out += "localframe\n";
      static constexpr std::string_view kRows[4][3] = {{"alp1=", "alp2=", "alp3="},
                                                       {"bet1=", "bet2=", "bet3="},
                                                       {"gam1=", "gam2=", "gam3="},
                                                       {"coo1=", "coo2=", "coo3="}};
      const std::array<Real, 3>* rows[] = {&frame.alpha, &frame.beta, &frame.gamma, &frame.shift};
      for (int r = 0; r < 4; ++r) append_continuation(out, kRows[r], rows[r]->data(), 3);
      break;
    }
    case ContactorLayout::polygon:
      append_blanks(out, 2);
      out += "nb_vertex=";
      append_fortran_i(out, static_cast<std::int64_t>(c.vertices.size()), 7);
      out += '\n';
      append_vertices(out, *kind, c.vertices);
      break;
    case ContactorLayout::polyhedron:
      append_polyhedron(out, static_cast<std::int64_t>(c.vertices.size()),
                        static_cast<std::int64_t>(c.faces.size()));
      append_vertices(out, *kind, c.vertices);
      append_faces(out, c.faces);
      break;
    case ContactorLayout::polyhedron_patches:
      append_blanks(out, 2);
      out += "nb_patch =";
      append_fortran_i(out, static_cast<std::int64_t>(c.patches.size()), 7);
      out += '\n';
      for (const auto& patch : c.patches) {
        append_blanks(out, 27);
        append_polyhedron(out, static_cast<std::int64_t>(patch.vertices.size()),
                          static_cast<std::int64_t>(patch.faces.size()));
        append_vertices(out, *kind, patch.vertices);
        append_faces(out, patch.faces);
      }
      break;
    case ContactorLayout::deformable_polyhedron:
      append_polyhedron(out, c.nodes.empty() ? 0 : c.nodes[0].value,
                        static_cast<std::int64_t>(c.faces.size()));
      append_faces(out, c.faces);
      break;
    case ContactorLayout::node_point: {
      static constexpr std::string_view kExtra[] = {"apab=", "bdyr=", "brpm="};
      append_node_ranks(out, c.nodes, 0, 2);
      append_pairs(out, kExtra, c.values.data(),
                   std::min<int>(kind->value_count, static_cast<int>(c.values.size())));
      out += '\n';
      break;
    }
    case ContactorLayout::node_polyline:
      append_node_ranks(out, c.nodes, 0, 2);
      out += '\n';
      // '+' lines: no colour (format 105).
      for (const auto& more : c.continuations) {
        append_contactor_head(out, '+', c.type.value, rank, "", false);
        append_node_ranks(out, more.nodes, 0, more.nodes.size());
        out += '\n';
      }
      break;
    case ContactorLayout::node_patch:
      append_node_ranks(out, c.nodes, 0, c.nodes.size());
      out += '\n';
      // '+' lines repeat the colour (mod_a_BDARY_xSpxx writer).
      for (const auto& more : c.continuations) {
        append_contactor_head(out, '+', c.type.value, rank, c.color.value);
        append_node_ranks(out, more.nodes, 0, more.nodes.size());
        out += '\n';
      }
      break;
  }
}

void append_body(std::string& out, const Body& body, std::int64_t rank) {
  static constexpr std::string_view kCoordinateLabels[] = {
      "coo1=", "coo2=", "coo3=", "coo4=", "coo5=", "coo6="};
  out += "$bdyty\n ";
  out += body_type_keyword(body.type);
  if (body.type != BodyType::mailx) append_blanks(out, 2);  // MAILx (1X,A5,I7), rigid (1X,A5,2X,I7)
  append_fortran_i(out, rank, 7);
  out += "\n$blmty\n";
  if (body.rigid_bulk) {
    const RigidBulk& b = *body.rigid_bulk;
    out += " PLAIN";
    append_blanks(out, 2);
    append_fortran_i(out, 1, 5);
    out += "  behav  ";
    append_fortran_a(out, b.behav.value, 5);
    out += "  avrd=";
    append_fortran_d(out, b.avrd.value);
    if (body.type == BodyType::rbdy2) {
      out += "  gyrd=";
      append_fortran_d(out, b.gyrd.value);
      out += '\n';
    } else {
      // RBDY3: the principal inertia line is always echoed (zeros when not given).
      out += '\n';
      static constexpr std::string_view kInertia[] = {"I1  =", "I2  =", "I3  ="};
      append_continuation(out, kInertia, b.principal_inertia.data(), 3);
    }
  }
  std::int64_t element_rank = 0;
  for (const Element& e : body.elements) {
    // FORMAT(' Q4xxx',I7,2x,'nodes',8(I7)); continuation lines: 20 blanks then 8 I7.
    out += ' ';
    append_fortran_a(out, e.type.value, 5);
    append_fortran_i(out, ++element_rank, 7);
    out += "  nodes";
    for (std::size_t i = 0; i < e.nodes.size(); ++i) {
      if (i > 0 && i % 8 == 0) {
        out += '\n';
        append_blanks(out, 20);
      }
      append_fortran_i(out, e.nodes[i].value, 7);
    }
    out += '\n';
    for (const ModelReference& m : e.models) {
      append_blanks(out, 15);
      out += "model  ";
      append_fortran_a(out, m.model.value, 5);
      out += "  behav  ";
      append_fortran_a(out, m.behav.value, 5);
      out += '\n';
    }
  }
  out += "$nodty\n";
  std::int64_t node_rank = 0;
  for (const Node& n : body.nodes) {
    // (1X,A5,1X,I6,2X,5X,2X,5X,3(2X,A5,D14.7)) then 27 blanks + pairs.
    out += ' ';
    append_fortran_a(out, n.type.value, 5);
    append_blanks(out, 1);
    append_fortran_i(out, ++node_rank, 6);
    append_blanks(out, 14);
    const int count = static_cast<int>(n.coordinates.size());
    append_pairs(out, kCoordinateLabels, n.coordinates.data(), std::min(count, 3));
    out += '\n';
    if (count > 3) append_continuation(out, kCoordinateLabels + 3, n.coordinates.data() + 3, count - 3);
  }
  out += "$tacty\n";
  std::int64_t contactor_rank = 0;
  for (const Contactor& c : body.contactors) append_contactor(out, c, ++contactor_rank);
  out += "$$$$$$\n      \n";
}

}  // namespace

std::string write_bodies(const BodiesFile& file) {
  std::string out;
  out.reserve(4096 + file.bodies.size() * 700);
  out += kHeader;
  const int dimension = bodies_dimension(file);
  std::int64_t rank[3] = {0, 0, 0};
  auto write_group = [&](BodyType type) {
    for (const Body& body : file.bodies)
      if (body.type == type) append_body(out, body, ++rank[static_cast<int>(type)]);
  };
  write_group(BodyType::mailx);
  out += kDashes;
  if (dimension == 2) {
    write_group(BodyType::rbdy2);
    out += kDashes;
  } else {
    write_group(BodyType::rbdy3);
  }
  return out;
}

}  // namespace lmgc::grammar
