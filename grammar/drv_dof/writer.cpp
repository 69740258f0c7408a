#include "grammar/drv_dof/writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "grammar/common/fortran_format.hpp"

namespace lmgc::grammar {
namespace {

// Fixed text of LMGC90's echo (docs/lmgc90-facts/datbox-inputs.md §5 "Echo DRV_DOF.OUT").
constexpr std::string_view kHeader = "     \n! DOF\n     \n";
constexpr std::string_view kTemplate =
    "$dofty  numbr "
    "[CT......+......AMP..*..cos.(..OMEGA.*.time.+.PHI..)]...*...[RAMPI.....+.....RAMP.*.time]\n";
constexpr std::string_view kDashes =
    "!-----------------------------------------------------------------------\n";

// Within one dof number LMGC90 writes the imposed-velocity entries before the force ones.
int kind_order(const std::string& kind) {
  return (kind == "force" || kind == "flux") ? 1 : 0;
}

// The dofs of a node type NOnxx (n), 0 for another name.
int node_width(const std::string& type) {
  return type.size() == 5 && type.compare(0, 2, "NO") == 0 && type[2] >= '1' && type[2] <= '9' ? type[2] - '0'
                                                                                               : 0;
}

struct MergedNode {
  std::string type;
  std::vector<DrivenDof> dofs;
};

struct MergedBody {
  std::map<std::int64_t, MergedNode> nodes;  // by node number
};

// Bodies of one module, merged by rank (a rank given twice gathers its dofs).
std::map<std::int64_t, MergedBody> gather(const DrvDofFile& file, std::string_view type,
                                          std::string_view model) {
  std::map<std::int64_t, MergedBody> bodies;
  for (const DrvDofBody& body : file.bodies) {
    if (body.body_type.value != type || body.model.value != model) continue;
    MergedBody& merged = bodies[body.rank.value];
    for (const DrvDofNode& node : body.nodes) {
      MergedNode& target = merged.nodes[node.number.value];
      // A node given twice under two node types is written with the wider one (NO1xx < NO2xx < ...),
      // which holds the dofs of both blocks (LMGC90 writes a node's type from the mesh).
      if (target.type.empty() || node_width(node.node_type.value) > node_width(target.type))
        target.type = node.node_type.value;
      target.dofs.insert(target.dofs.end(), node.dofs.begin(), node.dofs.end());
    }
  }
  return bodies;
}

void write_dof_line(std::string& out, const DrivenDof& dof) {
  // 120 FORMAT(1X,A5,2X,I5,6(1X,D14.7)) / 121 FORMAT(1X,A5,2X,I5,1X,'evolution',1X,A40)
  out += ' ';
  append_fortran_a(out, dof.kind.value, 5);
  append_blanks(out, 2);
  append_fortran_i(out, dof.dof.value, 5);
  if (dof.uses_evolution) {
    out += " evolution ";
    append_fortran_a(out, dof.evolution_file.value, 40);
  } else {
    for (const Real& value : dof.parameters) {
      out += ' ';
      append_fortran_d(out, value.value);
    }
  }
  out += '\n';
}

void write_dofs(std::string& out, std::vector<DrivenDof> dofs) {
  std::stable_sort(dofs.begin(), dofs.end(), [](const DrivenDof& a, const DrivenDof& b) {
    if (a.dof.value != b.dof.value) return a.dof.value < b.dof.value;
    return kind_order(a.kind.value) < kind_order(b.kind.value);
  });
  for (const DrivenDof& dof : dofs) write_dof_line(out, dof);
}

std::size_t dof_total(const MergedBody& body) {
  std::size_t total = 0;
  for (const auto& [number, node] : body.nodes) total += node.dofs.size();
  return total;
}

// RBDY2: body (1X,A5,2X,I7), node (1X,A5,2X,I5), separator 6 blanks, dashed line after the module.
// RBDY3: body and node (1X,A5,I7), separator 1 blank, no dashed line.
void write_rigid_section(std::string& out, const DrvDofFile& file, bool rbdy3) {
  const std::string_view type = rbdy3 ? "RBDY3" : "RBDY2";
  for (const auto& [rank, body] : gather(file, type, "")) {
    if (dof_total(body) == 0) continue;
    for (const auto& [number, node] : body.nodes) {
      if (node.dofs.empty()) continue;
      out += "$bdyty\n ";
      out += type;
      if (!rbdy3) append_blanks(out, 2);
      append_fortran_i(out, rank, 7);
      // The body's own node type, whatever the DAT's node line says (LMGC90 ignores it there).
      out += "\n$nodty\n ";
      out += rbdy3 ? "NO6xx" : "NO3xx";
      if (rbdy3) {
        append_fortran_i(out, number, 7);
      } else {
        append_blanks(out, 2);
        append_fortran_i(out, number, 5);
      }
      out += '\n';
      out += kTemplate;
      write_dofs(out, node.dofs);
      out += rbdy3 ? "$$$$$$\n \n" : "$$$$$$\n      \n";
    }
  }
  if (!rbdy3) out += kDashes;
}

// MAILx: body (1X,A5,I7), `$model`, model line, then per driven node `$nodty`, node (1X,A5,I7),
// template, dofs; `$$$$$$` and 6 blanks per body; a dashed line after the module.
void write_mailx_section(std::string& out, const DrvDofFile& file, std::string_view model,
                         const DrvDofEchoSetup& setup) {
  for (const auto& [rank, body] : gather(file, "MAILx", model)) {
    if (dof_total(body) == 0) continue;
    out += "$bdyty\n MAILx";
    append_fortran_i(out, rank, 7);
    out += "\n$model\n ";
    out += model;
    out += '\n';
    for (const auto& [number, node] : body.nodes) {
      if (node.dofs.empty()) continue;
      out += "$nodty\n ";
      if (setup.node_type_from_mesh)
        out += setup.dimension == 3 ? "NO3xx" : "NO2xx";
      else
        append_fortran_a(out, node.type, 5);
      append_fortran_i(out, number, 7);
      out += '\n';
      out += kTemplate;
      write_dofs(out, node.dofs);
    }
    out += "$$$$$$\n      \n";
  }
  out += kDashes;
}

// A body of this module that drives a dof (a block without any is not echoed, so it cannot decide
// what the echo holds: the echo of the echo must be the echo).
bool has_body(const DrvDofFile& file, std::string_view type, std::string_view model) {
  return std::any_of(file.bodies.begin(), file.bodies.end(), [&](const DrvDofBody& body) {
    return body.body_type.value == type && body.model.value == model &&
           std::any_of(body.nodes.begin(), body.nodes.end(),
                       [](const DrvDofNode& n) { return !n.dofs.empty(); });
  });
}

}  // namespace

DrvDofEchoSetup drv_dof_echo_setup_of(const DrvDofFile& file) {
  DrvDofEchoSetup setup;
  setup.dimension = 2;
  if (has_body(file, "RBDY3", "")) {
    setup.dimension = 3;
  } else if (!has_body(file, "RBDY2", "")) {
    for (const DrvDofBody& body : file.bodies)
      if (body.model.value == "MECAx")
        for (const DrvDofNode& node : body.nodes)
          if (node.node_type.value == "NO3xx") setup.dimension = 3;
  }
  setup.meca_mailx = has_body(file, "MAILx", "MECAx");
  setup.ther_mailx = has_body(file, "MAILx", "THERM");
  setup.poro_mailx = has_body(file, "MAILx", "POROx");
  return setup;
}

std::string write_drv_dof(const DrvDofFile& file, const DrvDofEchoSetup& setup) {
  std::string out(kHeader);
  // Module order of the run: rigid, mecaMAILx, therMAILx, poroMAILx (state-and-outputs.md §1.1).
  if (setup.dimension != 3 || has_body(file, "RBDY2", "")) write_rigid_section(out, file, false);
  if (setup.dimension == 3 || has_body(file, "RBDY3", "")) write_rigid_section(out, file, true);
  if (setup.meca_mailx || has_body(file, "MAILx", "MECAx")) write_mailx_section(out, file, "MECAx", setup);
  if (setup.ther_mailx || has_body(file, "MAILx", "THERM")) write_mailx_section(out, file, "THERM", setup);
  if (setup.poro_mailx || has_body(file, "MAILx", "POROx")) write_mailx_section(out, file, "POROx", setup);
  return out;
}

std::string write_drv_dof(const DrvDofFile& file) {
  return write_drv_dof(file, drv_dof_echo_setup_of(file));
}

namespace {

// One REAL(8) item of gfortran's list-directed output (`write(nfich,*) x, fx`, how LMGC90 rewrites an
// evolution file): 17 significant digits, correctly rounded; F form when the rounded value lies in
// [0.1, 1e17) (and for zero), right-justified in 20 columns and followed by 5 blanks, else
// d.dddddddddddddddd with a three-digit exponent, right-justified in 25 columns.
void append_list_directed_real(std::string& out, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.16E", value);  // the 17 significant digits, and their exponent
  const char* e = std::strchr(buffer, 'E');
  const long exponent = e ? std::strtol(e + 1, nullptr, 10) : 0;
  std::string text;
  int width = 25;
  if (!std::isfinite(value)) {
    text = buffer;
  } else if (value == 0.0 || (exponent >= -1 && exponent < 17)) {
    std::snprintf(buffer, sizeof buffer, "%#.*f", value == 0.0 ? 16 : static_cast<int>(16 - exponent), value);
    text = buffer;
    width = 20;
  } else {
    char exponent_text[32];
    std::snprintf(exponent_text, sizeof exponent_text, "E%c%03ld", exponent < 0 ? '-' : '+',
                  std::labs(exponent));
    text.assign(buffer, static_cast<std::size_t>(e - buffer));
    text += exponent_text;
  }
  if (text.size() < static_cast<std::size_t>(width))
    out.append(static_cast<std::size_t>(width) - text.size(), ' ');
  out += text;
  if (width == 20) out.append(5, ' ');
}

}  // namespace

std::string write_evolution(const EvolutionFile& file) {
  std::string out;
  for (const EvolutionPoint& point : file.points) {
    out += ' ';
    append_list_directed_real(out, point.time.value);
    out += ' ';
    append_list_directed_real(out, point.value.value);
    out += '\n';
  }
  return out;
}

}  // namespace lmgc::grammar
