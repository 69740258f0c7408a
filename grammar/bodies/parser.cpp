// BODIES.DAT reader. docs/lmgc90-facts/datbox-inputs.md §1 (structure, cards), §0 (record rules), §9, §10.
#include "grammar/bodies/parser.hpp"

#include <algorithm>
#include <string>

#include "grammar/bodies/contactor_catalogue.hpp"
#include "grammar/common/card_reader.hpp"
#include "grammar/common/fortran_format.hpp"
#include "grammar/common/fortran_number.hpp"

namespace lmgc::grammar {
namespace {

// Value columns shared by rigid contactors, nodes and most continuation lines (§1.3, §1.4).
constexpr int kValueColumns[3][2] = {{35, 48}, {56, 69}, {77, 90}};
// Node-rank columns of MAILx contactors: 12-column period from column 35 (§1.5).
constexpr int kNodeRankFirst = 35;
constexpr int kNodeRankPeriod = 12;

bool is_blank(std::string_view text) {
  return text.find_first_not_of(" \t") == std::string_view::npos;
}

std::optional<BodyType> body_type_of(std::string_view keyword) {
  if (keyword == "RBDY2") return BodyType::rbdy2;
  if (keyword == "RBDY3") return BodyType::rbdy3;
  if (keyword == "MAILx") return BodyType::mailx;
  return std::nullopt;
}

enum class Section { none, bulk, nodes, contactors };

class BodiesParser {
 public:
  BodiesParser(const SourceText& source, DiagnosticSink& sink) : reader_(source, sink) {}

  BodiesFile parse() {
    BodiesFile file;
    if (!reader_.check_records()) return file;
    std::vector<Body> bodies;
    while (!reader_.at_end()) {
      const Line& line = reader_.peek();
      if (keyword_of(line.text) == "bdyty") {
        reader_.next();
        if (auto body = parse_body()) bodies.push_back(std::move(*body));
      } else {
        reader_.report("L1019", line, 1, static_cast<int>(std::max<std::size_t>(line.text.size(), 1)),
                       "line outside any body; LMGC90 skips it", "a body starts with a '$bdyty' line");
        reader_.next();
      }
    }
    // LMGC90 numbers bodies within their type and echoes MAILx, then rigid bodies (§1.6).
    const auto by_type = [](const Body& a, const Body& b) { return a.type < b.type; };
    if (!std::is_sorted(bodies.begin(), bodies.end(), by_type))
      std::stable_sort(bodies.begin(), bodies.end(), by_type);
    file.bodies = std::move(bodies);
    return file;
  }

 private:
  // After '$bdyty': the type line, then sections until '$$$$$$'.
  std::optional<Body> parse_body() {
    if (reader_.at_end()) {
      reader_.report_at_end("L1006", "file ends after '$bdyty'; a body type line is expected");
      return std::nullopt;
    }
    const Line& type_line = reader_.peek();
    const std::string_view keyword = keyword_of(type_line.text);
    const auto type = body_type_of(keyword);
    if (!type) {
      reader_.report("L1001", type_line, 2, 6, "unknown body type '" + std::string(keyword) + "'",
                     "body types are RBDY2, RBDY3 and MAILx, in columns 2-6");
      skip_to_end_of_body();
      return std::nullopt;
    }
    reader_.next();
    Body body;
    body.type = *type;
    body.type_span = reader_.span(type_line, 2, 6);
    body.number = ordinal(type_line, *type == BodyType::mailx ? 7 : 9, *type == BodyType::mailx ? 13 : 15);
    body_label_ = body_label(body);

    Section section = Section::none;
    while (!reader_.at_end()) {
      const Line& line = reader_.peek();
      const std::string_view kw = keyword_of(line.text);
      if (kw == "$$$$$") {
        reader_.next();
        finish_body(body, type_line);
        return body;
      }
      if (kw == "bdyty") {
        reader_.report("L1005", line, 1, 6, "'$bdyty' before the '$$$$$$' that ends the previous body",
                       "end every body with a '$$$$$$' line");
        finish_body(body, type_line);
        return body;
      }
      if (kw == "blmty" || kw == "nodty" || kw == "tacty") {
        const Section next = kw == "blmty"   ? Section::bulk
                             : kw == "nodty" ? Section::nodes
                                             : Section::contactors;
        if (next <= section) {
          reader_.report("L1013", line, 2, 6,
                         "section '$" + std::string(kw) +
                             "' out of order; LMGC90 reads '$blmty', '$nodty', '$tacty' "
                             "in this order and would lose it");
        }
        section = next;
        reader_.next();
        continue;
      }
      switch (section) {
        case Section::none:
          reader_.report("L1013", line, 2, 6, "card '" + std::string(kw) + "' before any '$blmty' section");
          reader_.next();
          break;
        case Section::bulk:
          parse_bulk_item(body);
          break;
        case Section::nodes:
          parse_node(body);
          break;
        case Section::contactors:
          parse_contactor(body);
          break;
      }
    }
    reader_.report_at_end("L1005", "file ends inside body " + body_label(body) + "; '$$$$$$' is missing");
    finish_body(body, type_line);
    return body;
  }

  void finish_body(Body& body, const Line& type_line) {
    if (body.nodes.empty()) {
      reader_.report("L1012", type_line, 2, 6,
                     "body " + body_label(body) + " has no node ('$nodty' section)");
    } else if (body.type != BodyType::mailx && body.nodes.size() != 1) {
      reader_.report("L1014", type_line, 2, 6,
                     "rigid body " + body_label(body) + " has " + std::to_string(body.nodes.size()) +
                         " nodes; LMGC90 requires exactly one");
    }
    if (body.type != BodyType::mailx && !body.rigid_bulk) {
      reader_.report("L1012", type_line, 2, 6,
                     "rigid body " + body_label(body) + " has no 'PLAIN' bulk line");
    }
  }

  std::string body_label(const Body& body) const {
    return std::string(body_type_keyword(body.type)) + " " + std::to_string(body.number.value);
  }

  void skip_to_end_of_body() {
    while (!reader_.at_end()) {
      const std::string_view kw = keyword_of(reader_.peek().text);
      if (kw == "bdyty") return;
      reader_.next();
      if (kw == "$$$$$") return;
    }
  }

  // Numbers LMGC90 does not read: kept, never an error.
  Ordinal ordinal(const Line& line, int first, int last) {
    const IntegerResult r = read_fortran_integer(columns(line.text, first, last));
    return Ordinal{r.error == NumberError::none ? r.value : 0, reader_.span(line, first, last)};
  }

  // The next significant line, which must be a continuation of the current card. A line starting
  // with '$' (or '$$$$$' in columns 2-6) ends the card instead: LMGC90 would read '$$$$$$',
  // '$bdyty', ... as data and lose the structure; we report it, leave it to the body loop, and
  // the card is dropped.
  const Line* continuation(const char* what) {
    if (reader_.at_end()) {
      reader_.report_at_end("L1006",
                            std::string("file ends where ") + what + " is expected" + card_context());
      return nullptr;
    }
    const Line& line = reader_.peek();
    if ((!line.text.empty() && line.text[0] == '$') || keyword_of(line.text) == "$$$$$") {
      const std::string_view head = columns(line.text, 1, 12);
      const std::string word(head.substr(0, std::min(head.find_first_of(" \t"), head.size())));
      reader_.report("L1013", line, 1, static_cast<int>(std::max<std::size_t>(word.size(), 1)),
                     "'" + word + "' line where " + what + " is expected" + card_context() +
                         "; LMGC90 would read this line as data",
                     "give the card all its lines, or correct its count");
      return nullptr;
    }
    return &reader_.next();
  }

  // " (contactor POLYG 1 of RBDY2 3)": the card being read, for messages.
  std::string card_context() const {
    return card_.empty() ? std::string() : " (" + card_ + " of " + body_label_ + ")";
  }

  void read_values(const Line& line, int count, std::vector<Real>& out) {
    for (int i = 0; i < count; ++i)
      out.push_back(reader_.real(line, kValueColumns[i][0], kValueColumns[i][1]));
  }

  std::array<Real, 3> read_triple(const Line& line) {
    return {reader_.real(line, 35, 48), reader_.real(line, 56, 69), reader_.real(line, 77, 90)};
  }

  // $blmty items: PLAIN for rigid bodies, finite elements for MAILx (§1.2, §1.5).
  void parse_bulk_item(Body& body) {
    const Line& line = reader_.next();
    const std::string_view kw = keyword_of(line.text);
    if (is_blank(kw)) {
      reader_.report("L1019", line, 1, static_cast<int>(line.text.size()),
                     "continuation line without a card; LMGC90 skips it");
      return;
    }
    if (body.type == BodyType::mailx) {
      parse_element(body, line);
      return;
    }
    if (kw != "PLAIN") {
      reader_.report(
          "L1001", line, 2, 6,
          "unknown bulk element '" + std::string(kw) + "' for a rigid body; LMGC90 requires 'PLAIN'");
      return;
    }
    if (body.rigid_bulk) {
      reader_.report("L1014", line, 2, 6,
                     "second 'PLAIN' line in body " + body_label(body) + "; LMGC90 reads only the first");
      return;
    }
    RigidBulk bulk;
    bulk.type = reader_.word(line, 2, 6);
    bulk.number = ordinal(line, 9, 13);
    bulk.behav = reader_.word(line, 23, 27);
    bulk.avrd = reader_.real(line, 35, 48);
    if (body.type == BodyType::rbdy2) bulk.gyrd = reader_.real(line, 56, 69);
    // RBDY3: an optional "I1 = I2 = I3 =" line, recognised by 'I1' in columns 30-31 (§1.2).
    if (body.type == BodyType::rbdy3 && !reader_.at_end()) {
      const Line& next = reader_.peek();
      if (columns(next.text, 30, 31) == "I1") {
        reader_.next();
        bulk.principal_inertia = read_triple(next);
      }
    }
    body.rigid_bulk = std::move(bulk);
  }

  void parse_element(Body& body, const Line& line) {
    const std::string_view kw = keyword_of(line.text);
    const ElementKind* kind = find_element_kind(kw);
    if (!kind) {
      reader_.report("L1001", line, 2, 6, "unknown finite element '" + std::string(kw) + "'",
                     "elements are S2xxx S3xxx T3xxx T6xxx Q4xxx Q8xxx H8xxx H20xx TE4xx TE10x PRI6x PRI15");
      return;
    }
    Element element;
    element.type = reader_.word(line, 2, 6);
    element.number = ordinal(line, 7, 13);
    card_ = "element " + element.type.value + " " + std::to_string(element.number.value);
    // Connectivity: I7 fields from column 21, eight per line (§1.5).
    const Line* current = &line;
    for (int i = 0; i < kind->node_count; ++i) {
      if (i > 0 && i % 8 == 0) {
        current = continuation("a connectivity line");
        if (!current) return;
      }
      const int first = 21 + 7 * (i % 8);
      element.nodes.push_back(reader_.integer(*current, first, first + 6));
    }
    // One or more model lines: columns 2-6 blank, 'model' in 16-20 (checked by LMGC90).
    while (!reader_.at_end() && is_blank(keyword_of(reader_.peek().text)) && reader_.peek().text.size() > 0 &&
           reader_.peek().text[0] != '+') {
      const Line& model_line = reader_.next();
      if (columns(model_line.text, 16, 20) != "model") {
        reader_.report("L1016", model_line, 16, 20,
                       "expected 'model' in columns 16-20 of the line under element " + std::string(kw));
        continue;
      }
      element.models.push_back({reader_.word(model_line, 23, 27), reader_.word(model_line, 37, 41)});
    }
    if (element.models.empty())
      reader_.report("L1012", line, 2, 6, "element " + std::string(kw) + " has no 'model' line");
    body.elements.push_back(std::move(element));
  }

  // $nodty items (§1.3): NOnxx with n values, three per line.
  void parse_node(Body& body) {
    const Line& line = reader_.next();
    const std::string_view kw = keyword_of(line.text);
    if (is_blank(kw)) {
      reader_.report("L1019", line, 1, static_cast<int>(line.text.size()),
                     "continuation line without a node; LMGC90 skips it");
      return;
    }
    const bool known =
        kw.size() == 5 && kw.substr(0, 2) == "NO" && kw[2] >= '1' && kw[2] <= '6' && kw.substr(3) == "xx";
    if (!known) {
      reader_.report("L1001", line, 2, 6, "unknown node type '" + std::string(kw) + "'",
                     "node types are NO1xx ... NO6xx (the digit is the number of dofs)");
      return;
    }
    const int count = kw[2] - '0';
    if (body.type == BodyType::rbdy3 && count != 6)
      reader_.report("L1001", line, 2, 6, "RBDY3 bodies need a 'NO6xx' node, not '" + std::string(kw) + "'");
    if (body.type == BodyType::rbdy2 && count != 3)
      reader_.report("L1001", line, 2, 6, "RBDY2 bodies need a 'NO3xx' node, not '" + std::string(kw) + "'");
    Node node;
    node.type = reader_.word(line, 2, 6);
    node.number = ordinal(line, 8, 13);
    card_ = "node " + node.type.value + " " + std::to_string(node.number.value);
    read_values(line, std::min(count, 3), node.coordinates);
    if (count > 3) {
      // Without its continuation line the node keeps zeros there, the values LMGC90 reads from
      // the blank columns of the line it takes instead (NO6xx values 4-6 are forced to 0 anyway).
      if (const Line* more = continuation("the node's continuation line"))
        read_values(*more, count - 3, node.coordinates);
      else
        node.coordinates.resize(static_cast<std::size_t>(count), Real{0.0, {}});
    }
    body.nodes.push_back(std::move(node));
  }

  // $tacty items (§1.4, §1.5), laid out by the contactor catalogue.
  void parse_contactor(Body& body) {
    const Line& line = reader_.next();
    const std::string_view kw = keyword_of(line.text);
    if (is_blank(kw)) {
      reader_.report("L1019", line, 1, static_cast<int>(line.text.size()),
                     "continuation line without a contactor; LMGC90 skips it");
      return;
    }
    const ContactorKind* kind = find_contactor_kind(kw);
    const unsigned mask = 1u << static_cast<unsigned>(body.type);
    if (!kind) {
      reader_.report("L1001", line, 2, 6, "unknown contactor '" + std::string(kw) + "'");
      return;
    }
    if ((kind->bodies & mask) == 0) {
      reader_.report("L1001", line, 2, 6,
                     "contactor '" + std::string(kw) + "' does not belong to " +
                         std::string(body_type_keyword(body.type)) + " bodies");
      return;
    }
    // The 2012 user's guide's pneumatic disks: LMGC90 2025 removed them, and its RBDY2 reader stops
    // on them ('tacty DISPx unknown'). Read (so the file still echoes), reported as an error.
    if (!kind->guide_only.empty()) reader_.report("L1001", line, 2, 6, std::string(kind->guide_only));
    Contactor c;
    c.type = reader_.word(line, 2, 6);
    c.number = ordinal(line, 9, 13);
    c.color = reader_.word(line, 23, 27);
    card_ = "contactor " + c.type.value + " " + std::to_string(c.number.value);
    switch (kind->layout) {
      case ContactorLayout::values:
        read_values(line, kind->value_count, c.values);
        break;
      case ContactorLayout::values_offset: {
        read_values(line, kind->value_count, c.values);
        const Line* offset = continuation("the contactor's offset line");
        if (!offset) return;
        read_values(*offset, kind->offset_count, c.values);
        break;
      }
      case ContactorLayout::values_frame:
        read_values(line, kind->value_count, c.values);
        if (!reader_.at_end() && columns(reader_.peek().text, 30, 39) == "localframe") {
          reader_.next();
          LocalFrame frame;
          std::array<Real, 3>* rows[] = {&frame.alpha, &frame.beta, &frame.gamma, &frame.shift};
          for (auto* row : rows) {
            const Line* frame_line = continuation("a 'localframe' line");
            if (!frame_line) return;
            *row = read_triple(*frame_line);
          }
          // The identity frame is LMGC90's default: stored as "no frame" (same echo).
          if (!(frame == LocalFrame{})) c.frame.push_back(frame);
        }
        break;
      case ContactorLayout::polygon: {
        const Integer count = reader_.integer(line, 40, 46);
        if (count.value < 1) {
          reader_.report("L1014", line, 40, 46, "polygon with " + std::to_string(count.value) + " vertices");
          return;
        }
        for (std::int64_t i = 0; i < count.value; ++i) {
          const Line* vertex = continuation("a polygon vertex line");
          if (!vertex) return;
          c.vertices.push_back({reader_.real(*vertex, 35, 48), reader_.real(*vertex, 56, 69), Real{0.0}});
        }
        break;
      }
      case ContactorLayout::polyhedron:
        if (!read_polyhedron(line, c.vertices, c.faces)) return;
        break;
      case ContactorLayout::polyhedron_patches: {
        auto patches = reader_.list_integer(line, 40, 47, "the number of patches");
        if (!patches) return;
        for (std::int64_t p = 0; p < patches->value; ++p) {
          const Line* header = continuation("a POLYF patch header");
          if (!header) return;
          PolyhedronPatch patch;
          if (!read_polyhedron(*header, patch.vertices, patch.faces)) return;
          c.patches.push_back(std::move(patch));
        }
        break;
      }
      case ContactorLayout::deformable_polyhedron: {
        auto nv = reader_.list_integer(line, 40, 47, "the number of vertices");
        auto nf = reader_.list_integer(line, 60, 67, "the number of faces");
        if (!nv || !nf) return;
        c.nodes.push_back(*nv);
        if (!read_faces(nf->value, c.faces)) return;
        break;
      }
      case ContactorLayout::node_point:
        c.nodes.push_back(reader_.integer(line, 35, 39));
        c.nodes.push_back(reader_.integer(line, 47, 51));
        c.values.push_back(reader_.real(line, 59, 72));
        if (kind->value_count == 3) {
          c.values.push_back(reader_.real(line, 80, 93));
          c.values.push_back(reader_.real(line, 101, 114));
        }
        break;
      case ContactorLayout::node_polyline:
        c.nodes.push_back(reader_.integer(line, 35, 39));
        c.nodes.push_back(reader_.integer(line, 47, 51));
        read_plus_lines(*kind, c, 2);
        break;
      case ContactorLayout::node_patch: {
        const int count = kind->patch_nodes ? kind->patch_nodes : patch_node_count(line);
        read_node_ranks(line, count, c.nodes);
        read_plus_lines(*kind, c, count);
        break;
      }
    }
    body.contactors.push_back(std::move(c));
  }

  // CSpxx/ASpxx: the number of nodes is told by the labels (§1.5).
  static int patch_node_count(const Line& line) {
    if (columns(line.text, 114, 117) == "nodh") return 8;
    if (columns(line.text, 90, 93) == "nodf") return 6;
    if (columns(line.text, 66, 69) == "nodd") return 4;
    return 3;
  }

  void read_node_ranks(const Line& line, int count, std::vector<Integer>& out) {
    for (int i = 0; i < count; ++i) {
      const int first = kNodeRankFirst + kNodeRankPeriod * i;
      out.push_back(reader_.integer(line, first, first + 4));
    }
  }

  // Lines starting with '+' and the contactor's keyword continue it (ALpxx segments, patches).
  void read_plus_lines(const ContactorKind& kind, Contactor& c, int count) {
    while (!reader_.at_end()) {
      const Line& next = reader_.peek();
      if (next.text.empty() || next.text[0] != '+' || columns(next.text, 2, 6) != kind.keyword) return;
      reader_.next();
      ContactorContinuation more;
      const int n = kind.layout == ContactorLayout::node_patch && kind.patch_nodes == 0
                        ? patch_node_count(next)
                        : count;
      read_node_ranks(next, n, more.nodes);
      c.continuations.push_back(std::move(more));
    }
  }

  bool read_polyhedron(const Line& header, std::vector<std::array<Real, 3>>& vertices,
                       std::vector<std::array<Integer, 3>>& faces) {
    auto nv = reader_.list_integer(header, 40, 47, "the number of vertices");
    auto nf = reader_.list_integer(header, 60, 67, "the number of faces");
    if (!nv || !nf) return false;
    if (nv->value < 1 || nf->value < 1) {
      reader_.report("L1014", header, 40, 67,
                     "polyhedron with " + std::to_string(nv->value) + " vertices and " +
                         std::to_string(nf->value) + " faces");
      return false;
    }
    for (std::int64_t i = 0; i < nv->value; ++i) {
      const Line* vertex = continuation("a polyhedron vertex line");
      if (!vertex) return false;
      vertices.push_back(read_triple(*vertex));
    }
    return read_faces(nf->value, faces);
  }

  bool read_faces(std::int64_t count, std::vector<std::array<Integer, 3>>& faces) {
    for (std::int64_t i = 0; i < count; ++i) {
      const Line* face = continuation("a face line");
      if (!face) return false;
      std::array<Integer, 3> ids;
      const int ranges[3][2] = {{35, 47}, {56, 68}, {77, 89}};
      for (int k = 0; k < 3; ++k) {
        auto id = reader_.list_integer(*face, ranges[k][0], ranges[k][1], "a face vertex index");
        if (!id) return false;
        ids[static_cast<std::size_t>(k)] = *id;
      }
      faces.push_back(ids);
    }
    return true;
  }

  CardReader reader_;
  std::string body_label_;  // the body being read, for messages
  std::string card_;        // the multi-line card being read, for messages
};

}  // namespace

std::string_view body_type_keyword(BodyType type) {
  switch (type) {
    case BodyType::rbdy2:
      return "RBDY2";
    case BodyType::rbdy3:
      return "RBDY3";
    case BodyType::mailx:
      return "MAILx";
  }
  return "RBDY2";
}

int bodies_dimension(const BodiesFile& file) {
  for (const Body& body : file.bodies) {
    if (body.type == BodyType::rbdy3) return 3;
    if (body.type == BodyType::rbdy2) return 2;
    for (const Node& node : body.nodes)
      if (node.type.value == "NO3xx") return 3;
  }
  return 2;
}

BodiesFile parse_bodies(const SourceText& source, DiagnosticSink& sink) {
  return BodiesParser(source, sink).parse();
}

}  // namespace lmgc::grammar
