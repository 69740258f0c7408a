#include "solver/io/state_files_2d.hpp"

namespace lmgc::solver {

grammar::DofFile dof_file_2d(const Scene2D& scene, const RunState2D& state) {
  grammar::DofFile file;
  file.step = grammar::Integer{state.step};
  file.time = grammar::Real{state.time};
  grammar::DofSection section;
  section.closed = true;
  const RigidBodies2D& b = scene.bodies;
  section.bodies.reserve(b.size());
  for (std::size_t i = 0; i < b.size(); ++i) {
    grammar::DofBody body;
    body.body_type = grammar::Word{"RBDY2"};
    body.number = grammar::Integer{static_cast<std::int64_t>(i + 1)};
    grammar::DofNode node;
    node.node_type = grammar::Word{"NO3xx"};
    node.number = grammar::Integer{1};
    for (int d = 0; d < 3; ++d) {
      node.x.push_back(grammar::Real{b.displacement[i](d)});
      node.v.push_back(grammar::Real{b.velocity[i](d)});
    }
    body.nodes.push_back(std::move(node));
    section.bodies.push_back(std::move(body));
  }
  file.sections.push_back(std::move(section));
  // The MAILx module writes its dashed line even when it has no body (state-and-outputs.md §1.3).
  file.sections.push_back(grammar::DofSection{{}, true});
  return file;
}

}  // namespace lmgc::solver
