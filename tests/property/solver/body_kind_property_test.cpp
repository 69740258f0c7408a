// Properties of the body-kind interface (solver/model/body_kind.hpp), held by every kind: a
// reaction on one contact moves another contact's local velocity by their coupling block, the
// coupling of two contacts is the transpose of the reverse coupling, and a contact's own coupling
// is its Delassus block.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <Eigen/Geometry>

#include "solver/model/body_kind.hpp"

namespace lmgc::solver {
namespace {

constexpr int kBodies = 3;

double value() {
  return *rc::gen::inRange(-1000, 1001) / 100.0;
}
double positive() {
  return *rc::gen::inRange(1, 1001) / 100.0;
}
// Two different bodies of the kBodies: contacts may share one, both or none.
std::pair<std::int32_t, std::int32_t> body_pair() {
  const std::int32_t a = *rc::gen::inRange(0, kBodies);
  std::int32_t b = *rc::gen::inRange(0, kBodies - 1);
  if (b >= a) ++b;
  return {a, b};
}

Interaction2D contact_2d() {
  Interaction2D c;
  std::tie(c.candidate_body, c.antagonist_body) = body_pair();
  const double angle = value();
  c.normal = Eigen::Vector2d(std::cos(angle), std::sin(angle));
  c.lever_candidate = Eigen::Vector2d(value(), value());
  c.lever_antagonist = Eigen::Vector2d(value(), value());
  return c;
}
RigidBodies2D bodies_2d() {
  RigidBodies2D b;
  for (int i = 0; i < kBodies; ++i) b.inverse_mass.emplace_back(positive(), 0.0, positive());
  for (auto& m : b.inverse_mass) m.y() = m.x();
  return b;
}
std::vector<Eigen::Vector3d> velocities_2d() {
  std::vector<Eigen::Vector3d> v;
  for (int i = 0; i < kBodies; ++i) v.emplace_back(value(), value(), value());
  return v;
}

Interaction3D contact_3d() {
  Interaction3D c;
  std::tie(c.candidate_body, c.antagonist_body) = body_pair();
  const Eigen::Vector3d axis = Eigen::Vector3d(value(), value(), value()) + Eigen::Vector3d(0.0, 0.0, 20.0);
  c.frame = Eigen::AngleAxisd(value(), axis.normalized()).toRotationMatrix();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      c.lever_candidate(i, j) = value();
      c.lever_antagonist(i, j) = value();
    }
  return c;
}
RigidBodies3D bodies_3d() {
  RigidBodies3D b;
  for (int i = 0; i < kBodies; ++i) {
    const double m = positive();
    Vector6d inverse;
    inverse << m, m, m, positive(), positive(), positive();
    b.inverse_mass.push_back(inverse);
  }
  return b;
}
std::vector<Vector6d> velocities_3d() {
  std::vector<Vector6d> v(kBodies);
  for (auto& x : v)
    for (int k = 0; k < 6; ++k) x(k) = value();
  return v;
}

// Δu_d from a reaction r on c, against coupling_block(d, c) r.
template <class Kind>
void reaction_moves_by_coupling(const typename Kind::Contact& c, const typename Kind::Contact& d,
                                const typename Kind::Bodies& bodies, typename Kind::Velocities v,
                                const typename Kind::Local& r) {
  const typename Kind::Local before = Kind::local_velocity(d, v);
  Kind::inject(c, r, bodies, v);
  const typename Kind::Local moved = Kind::local_velocity(d, v) - before;
  const typename Kind::Local expected = Kind::coupling_block(d, c, bodies) * r;
  RC_ASSERT((moved - expected).norm() <= 1e-9 * (1.0 + expected.norm() + before.norm()));
}

RC_GTEST_PROP(BodyKind, ReactionOnOneContactMovesAnotherByTheirCouplingBlock2D, ()) {
  reaction_moves_by_coupling<RigidBodyKind2D>(contact_2d(), contact_2d(), bodies_2d(), velocities_2d(),
                                              Eigen::Vector2d(value(), value()));
}

RC_GTEST_PROP(BodyKind, ReactionOnOneContactMovesAnotherByTheirCouplingBlock3D, ()) {
  reaction_moves_by_coupling<RigidBodyKind3D>(contact_3d(), contact_3d(), bodies_3d(), velocities_3d(),
                                              Eigen::Vector3d(value(), value(), value()));
}

RC_GTEST_PROP(BodyKind, CouplingOfTwoContactsIsTheTransposeOfTheReverse, ()) {
  const RigidBodies2D b2 = bodies_2d();
  const Interaction2D c2 = contact_2d(), d2 = contact_2d();
  RC_ASSERT((coupling_block(c2, d2, b2.inverse_mass) - coupling_block(d2, c2, b2.inverse_mass).transpose())
                .norm() <= 1e-9 * (1.0 + coupling_block(c2, d2, b2.inverse_mass).norm()));
  const RigidBodies3D b3 = bodies_3d();
  const Interaction3D c3 = contact_3d(), d3 = contact_3d();
  RC_ASSERT((coupling_block(c3, d3, b3) - coupling_block(d3, c3, b3).transpose()).norm() <=
            1e-9 * (1.0 + coupling_block(c3, d3, b3).norm()));
}

RC_GTEST_PROP(BodyKind, OwnCouplingBlockIsTheDelassusBlock3D, ()) {
  const RigidBodies3D b = bodies_3d();
  const Interaction3D c = contact_3d();
  RC_ASSERT((coupling_block(c, c, b) - delassus_block(c, b)).norm() <=
            1e-9 * (1.0 + delassus_block(c, b).norm()));
}

// Two contacts on bodies they do not share do not couple.
TEST(BodyKind, ContactsWithoutACommonBodyDoNotCouple) {
  RigidBodies3D b;
  b.inverse_mass.assign(4, Vector6d::Ones());
  Interaction3D c, d;
  c.candidate_body = 0, c.antagonist_body = 1;
  d.candidate_body = 2, d.antagonist_body = 3;
  c.frame = d.frame = Eigen::Matrix3d::Identity();
  c.lever_candidate = c.lever_antagonist = d.lever_candidate = d.lever_antagonist = Eigen::Matrix3d::Ones();
  EXPECT_TRUE(coupling_block(c, d, b).isZero(0.0));
  d.antagonist_body = 1;  // now they share body 1, both as antagonist
  EXPECT_FALSE(coupling_block(c, d, b).isZero(0.0));
}

}  // namespace
}  // namespace lmgc::solver
