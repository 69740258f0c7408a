#include "solver/bodies/rigid_bodies_2d.hpp"

namespace lmgc::solver {

void RigidBodies2D::resize(std::size_t n) {
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  for (auto* v : {&reference, &displacement_begin, &displacement, &velocity_begin, &velocity, &velocity_free,
                  &inverse_mass, &external_force, &impulse})
    v->assign(n, zero);
  mass.assign(n, 0.0);
  inertia.assign(n, 0.0);
  avrd.assign(n, 0.0);
  gyrd.assign(n, 0.0);
  bulk_behav.assign(n, 0);
  driven_mask.assign(n, 0);
  visible.assign(n, 1);
}

}  // namespace lmgc::solver
