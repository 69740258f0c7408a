#pragma once
// Structured meshes for the finite-element tests: a rectangle [0, L] × [0, H] cut into nx × ny cells,
// each cell one Q4, two T3, one Q8 or two T6 (nodes numbered row after row, mid-side nodes after).
#include <map>
#include <utility>

#include "solver/fem/linear_body.hpp"

namespace lmgc::test {

inline solver::fem::MeshBody rectangle(solver::fem::ElementKind kind, int nx, int ny, double length,
                                       double height, const solver::fem::Material& material,
                                       solver::fem::Hypothesis hypothesis) {
  using solver::fem::ElementKind;
  solver::fem::MeshBody body;
  body.dimension = 2;
  body.hypothesis = hypothesis;
  body.materials = {material};
  const bool quadratic = kind == ElementKind::Q8 || kind == ElementKind::T6;
  // Grid of (2nx+1) × (2ny+1) points when quadratic (every other one a vertex), else (nx+1) × (ny+1).
  const int sx = quadratic ? 2 * nx : nx, sy = quadratic ? 2 * ny : ny;
  std::map<std::pair<int, int>, std::int32_t> index;
  const auto node = [&](int i, int j) {
    const auto key = std::make_pair(i, j);
    auto it = index.find(key);
    if (it != index.end()) return it->second;
    const auto id = static_cast<std::int32_t>(body.coordinates.size() / 2);
    body.coordinates.push_back(length * i / sx);
    body.coordinates.push_back(height * j / sy);
    index.emplace(key, id);
    return id;
  };
  const int s = quadratic ? 2 : 1;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int x0 = s * i, y0 = s * j, x1 = x0 + s, y1 = y0 + s;
      solver::fem::MeshElement e;
      e.kind = kind;
      switch (kind) {
        case ElementKind::Q4:
          e.nodes = {node(x0, y0), node(x1, y0), node(x1, y1), node(x0, y1)};
          body.elements.push_back(e);
          break;
        case ElementKind::Q8:
          e.nodes = {node(x0, y0),     node(x1, y0),     node(x1, y1),     node(x0, y1),
                     node(x0 + 1, y0), node(x1, y0 + 1), node(x0 + 1, y1), node(x0, y0 + 1)};
          body.elements.push_back(e);
          break;
        case ElementKind::T3:
          e.nodes = {node(x0, y0), node(x1, y0), node(x1, y1)};
          body.elements.push_back(e);
          e.nodes = {node(x0, y0), node(x1, y1), node(x0, y1)};
          body.elements.push_back(e);
          break;
        case ElementKind::T6:
          e.nodes = {node(x0, y0),     node(x1, y0),     node(x1, y1),
                     node(x0 + 1, y0), node(x1, y0 + 1), node(x0 + 1, y0 + 1)};
          body.elements.push_back(e);
          e.nodes = {node(x0, y0),         node(x1, y1),     node(x0, y1),
                     node(x0 + 1, y0 + 1), node(x0 + 1, y1), node(x0, y0 + 1)};
          body.elements.push_back(e);
          break;
        default:
          break;
      }
    }
  return body;
}

}  // namespace lmgc::test
