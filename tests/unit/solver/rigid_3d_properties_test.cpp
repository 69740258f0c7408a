// RBDY3 mass, principal inertia, principal frame and centre of inertia from BODIES.DAT data, as
// LMGC90's read_bodies / comp_mass_RBDY3 compute them. docs/lmgc90-facts/datbox-inputs.md §1.2, §1.4,
// numerics.md §1.2; LMGC90 src/Core/rigid_3D/mod_RBDY3.f90 :941-1237, :3731-3807.
#include "solver/bodies/rigid_3d_properties.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/support/shared_data.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

constexpr double pi = lmgc_pi;

Rigid3DContactorShape sphere(double r) {
  return {"SPHER", r, Vector3d::Zero(), Vector3d::Zero(), Matrix3d::Identity(), {}, {}};
}
Rigid3DContactorShape ball(double r, const Vector3d& shift) {
  return {"SPHEb", r, shift, Vector3d::Zero(), Matrix3d::Identity(), {}, {}};
}
Rigid3DContactorShape plan(const Vector3d& half_axes, const Matrix3d& frame = Matrix3d::Identity(),
                           const Vector3d& shift = Vector3d::Zero()) {
  return {"PLANx", 0.0, shift, half_axes, frame, {}, {}};
}

double ball_volume(double r) {
  return 4.0 / 3.0 * pi * r * r * r;
}

// Independent geometric inertia tensor of a set of contactors about `centre` (input axes).
Matrix3d tensor_about(const std::vector<Rigid3DContactorShape>& cs, const Vector3d& centre) {
  Matrix3d t = Matrix3d::Zero();
  for (const auto& c : cs) {
    double v = 0.0;
    Vector3d moments = Vector3d::Zero();
    Matrix3d e = Matrix3d::Identity();
    if (c.type == "PLANx") {
      const Vector3d& a = c.half_axes;
      v = 8.0 * a.prod();
      moments = v / 3.0 *
                Vector3d(a.y() * a.y() + a.z() * a.z(), a.x() * a.x() + a.z() * a.z(),
                         a.x() * a.x() + a.y() * a.y());
      e = c.frame;
    } else {
      v = ball_volume(c.radius);
      moments.setConstant(0.4 * c.radius * c.radius * v);
    }
    const Vector3d d = c.shift - centre;
    t += e * moments.asDiagonal() * e.transpose() +
         v * (d.squaredNorm() * Matrix3d::Identity() - d * d.transpose());
  }
  return t;
}

// --- single contactor ---------------------------------------------------------------------------

TEST(Rigid3DProperties, SingleSphereGetsTheBallsMassAndTwoFifthsMR2) {
  const double rho = 2500.0, r = 0.01;
  const auto p = rigid_3d_properties(rho, 0.0, Vector3d::Zero(), {sphere(r)});
  const double v = ball_volume(r);
  EXPECT_NEAR(p.volume, v, 1e-15 * v);
  EXPECT_NEAR(p.avrd, r, 1e-15);
  EXPECT_NEAR(p.mass, rho * v, 1e-15 * rho * v);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.inertia[k], 0.4 * p.mass * r * r, 1e-12 * p.mass * r * r);
  EXPECT_TRUE(p.frame.isIdentity(0.0));
  EXPECT_TRUE(p.centre_shift.isZero(0.0));
  ASSERT_EQ(p.contactor_shifts.size(), 1u);
  EXPECT_TRUE(p.contactor_shifts[0].isZero(0.0));
  EXPECT_FALSE(p.frame_is_placeholder);
  EXPECT_EQ(p.ignored_contactors, 0u);
}

TEST(Rigid3DProperties, UsesLmgc90sSinglePrecisionPi) {
  // PI_g = 3.14159265358979323846 without d0 (shared/mod_overall.f90:358).
  EXPECT_EQ(lmgc_pi, 3.1415927410125732);
  const auto p = rigid_3d_properties(1.0, 0.0, Vector3d::Zero(), {sphere(1.0)});
  EXPECT_DOUBLE_EQ(p.volume, 4.0 * 3.1415927410125732 / 3.0);
}

TEST(Rigid3DProperties, GivenAvrdSetsTheMassButTheSingleContactorKeepsItsOwnInertia) {
  // mod_RBDY3.f90:979-980 (volume from avrd), :1012-1014 (inertia = the contactor's).
  const double rho = 1000.0, r = 0.01, avrd = 0.02;
  const auto p = rigid_3d_properties(rho, avrd, Vector3d::Zero(), {sphere(r)});
  EXPECT_EQ(p.avrd, avrd);
  EXPECT_NEAR(p.mass, rho * ball_volume(avrd), 1e-14 * rho * ball_volume(avrd));
  const double i_contactor = 0.4 * r * r * ball_volume(r);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.geometric_inertia[k], i_contactor, 1e-14 * i_contactor);
  EXPECT_NEAR(p.inertia[0], rho * i_contactor, 1e-14 * rho * i_contactor);
}

TEST(Rigid3DProperties, TheInertiaLineIsIgnoredForASingleSphere) {
  // The SPHER reader overwrites the I1..I3 copied from the I-line (mod_RBDY3.f90:812-836).
  const double r = 0.005;
  const auto p = rigid_3d_properties(580.0, 0.0, Vector3d(1.0, 2.0, 3.0), {sphere(r)});
  const double i = 0.4 * r * r * ball_volume(r);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.geometric_inertia[k], i, 1e-14 * i);
  EXPECT_FALSE(p.frame_is_placeholder);
}

TEST(Rigid3DProperties, SingleOffsetBallMovesTheCentreAndGetsShiftZero) {
  // mod_RBDY3.f90:996-998: cooref += shift, shift = 0.
  const Vector3d s(0.1, -0.2, 0.3);
  const auto p = rigid_3d_properties(1.0, 0.0, Vector3d::Zero(), {ball(0.05, s)});
  EXPECT_TRUE(p.centre_shift.isApprox(s, 0.0));
  EXPECT_TRUE(p.contactor_shifts[0].isZero(0.0));
}

TEST(Rigid3DProperties, PlanxWallIsABoxOfHalfAxesInItsLocalFrame) {
  const double rho = 580.0;
  const Vector3d a(0.5, 0.4, 0.01);
  const Matrix3d e = Eigen::AngleAxisd(0.3, Vector3d(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
  const Vector3d coo(0.01, 0.02, -0.03);
  const auto p = rigid_3d_properties(rho, 0.0, Vector3d::Zero(), {plan(a, e, coo)});
  const double v = 8.0 * a.x() * a.y() * a.z();
  EXPECT_NEAR(p.volume, v, 1e-15 * v);
  EXPECT_NEAR(p.avrd, std::cbrt(0.75 * v / pi), 1e-14);
  EXPECT_NEAR(p.mass, rho * v, 1e-15 * rho * v);
  // Box of sides 2a: I1 = m (L2² + L3²)/12 = m (a2² + a3²)/3.
  const Vector3d expected =
      p.mass / 3.0 *
      Vector3d(a.y() * a.y() + a.z() * a.z(), a.x() * a.x() + a.z() * a.z(), a.x() * a.x() + a.y() * a.y());
  EXPECT_TRUE(p.inertia.isApprox(expected, 1e-14));
  EXPECT_TRUE(p.frame.isApprox(e, 0.0));               // the embedded frame becomes the body frame (:1019)
  EXPECT_TRUE(p.contactor_frames[0].isIdentity(0.0));  // :1025
  EXPECT_TRUE(p.centre_shift.isApprox(coo, 0.0));
}

TEST(Rigid3DProperties, PlanxWallOf1ClusterSP2PLMatchesItsBodiesOutEcho) {
  // Body 1: axe = (1e-2, 1e-2, 2e-3) → avrd 0.7255663D-02, I = 0.5546667D-10 0.5546667D-10 0.1066667D-09.
  const auto p = rigid_3d_properties(580.0, 0.0, Vector3d::Zero(), {plan(Vector3d(1e-2, 1e-2, 2e-3))});
  EXPECT_NEAR(p.avrd, 0.7255663e-02, 5e-10);
  EXPECT_NEAR(p.geometric_inertia[0], 0.5546667e-10, 5e-17);
  EXPECT_NEAR(p.geometric_inertia[1], 0.5546667e-10, 5e-17);
  EXPECT_NEAR(p.geometric_inertia[2], 0.1066667e-09, 5e-16);
  EXPECT_NEAR(p.mass, 580.0 * 1.6e-6, 1e-15);
}

// --- several contactors -------------------------------------------------------------------------

TEST(Rigid3DProperties, ClusterOfTwoEqualBallsAddsTheParallelAxisTerms) {
  const double rho = 1000.0, r = 0.01, l = 0.02;
  const Vector3d node_offset(0.1, 0.2, 0.3);  // both balls shifted: the centre moves by it
  const auto p = rigid_3d_properties(
      rho, 0.0, Vector3d::Zero(),
      {ball(r, node_offset + Vector3d(l, 0.0, 0.0)), ball(r, node_offset - Vector3d(l, 0.0, 0.0))});
  const double v = ball_volume(r);
  EXPECT_NEAR(p.volume, 2.0 * v, 1e-15 * v);
  EXPECT_NEAR(p.avrd, std::cbrt(0.75 * 2.0 * v / pi), 1e-15);
  EXPECT_NEAR(p.mass, 2.0 * rho * v, 1e-12 * rho * v);
  EXPECT_TRUE(p.centre_shift.isApprox(node_offset, 1e-14));
  // The tensor is diagonal: moments kept in place (x, y, z), not sorted; frame identity.
  const double m = p.mass;
  EXPECT_NEAR(p.inertia[0], 0.4 * m * r * r, 1e-12 * m * r * r);
  EXPECT_NEAR(p.inertia[1], 0.4 * m * r * r + m * l * l, 1e-12 * m * l * l);
  EXPECT_NEAR(p.inertia[2], 0.4 * m * r * r + m * l * l, 1e-12 * m * l * l);
  EXPECT_TRUE(p.frame.isIdentity(0.0));
  EXPECT_TRUE(p.contactor_shifts[0].isApprox(Vector3d(l, 0.0, 0.0), 1e-12));
  EXPECT_TRUE(p.contactor_shifts[1].isApprox(Vector3d(-l, 0.0, 0.0), 1e-12));
}

TEST(Rigid3DProperties, TiltedClusterIsDiagonalisedAscendingInARightHandedFrame) {
  const double r1 = 0.01, r2 = 0.02;
  const Vector3d axis = Vector3d(1.0, 1.0, 0.5).normalized();
  const std::vector<Rigid3DContactorShape> cs = {ball(r1, -0.015 * axis), ball(r2, 0.02 * axis)};
  const auto p = rigid_3d_properties(1.0, 0.0, Vector3d::Zero(), cs);
  const double v1 = ball_volume(r1), v2 = ball_volume(r2);
  const Vector3d centre = (v1 * cs[0].shift + v2 * cs[1].shift) / (v1 + v2);
  EXPECT_TRUE(p.centre_shift.isApprox(centre, 1e-13));
  // Ascending: the axis of the cluster carries the smallest moment; two equal ones follow.
  EXPECT_LT(p.inertia[0], p.inertia[1]);
  EXPECT_NEAR(p.inertia[1], p.inertia[2], 1e-12 * p.inertia[2]);
  EXPECT_NEAR(std::abs(p.frame.col(0).dot(axis)), 1.0, 1e-12);
  EXPECT_GT(p.frame.col(0).dot(axis), 0.0);  // the sign LAPACK's dsyevd gives, as in LMGC90
  EXPECT_NEAR(p.frame.determinant(), 1.0, 1e-12);
  EXPECT_TRUE((p.frame.transpose() * p.frame).isIdentity(1e-12));
  const Matrix3d t = tensor_about(cs, centre);
  EXPECT_TRUE((p.frame * p.geometric_inertia.asDiagonal() * p.frame.transpose()).isApprox(t, 1e-10));
  // Shifts are re-expressed in the principal frame (:1175-1181).
  for (std::size_t i = 0; i < cs.size(); ++i)
    EXPECT_TRUE((p.frame * p.contactor_shifts[i]).isApprox(cs[i].shift - centre, 1e-12));
}

TEST(Rigid3DProperties, ClusterWithARotatedPlanxUsesItsEmbeddedFrameAndMapsIt) {
  const Matrix3d e = Eigen::AngleAxisd(0.7, Vector3d(0.2, -1.0, 0.4).normalized()).toRotationMatrix();
  const std::vector<Rigid3DContactorShape> cs = {
      plan(Vector3d(0.03, 0.02, 0.005), e, Vector3d(0.01, 0.0, 0.0)),
      ball(0.01, Vector3d(-0.02, 0.01, 0.005))};
  const auto p = rigid_3d_properties(7800.0, 0.0, Vector3d::Zero(), cs);
  const double vp = 8.0 * 0.03 * 0.02 * 0.005, vb = ball_volume(0.01);
  const Vector3d centre = (vp * cs[0].shift + vb * cs[1].shift) / (vp + vb);
  EXPECT_TRUE(p.centre_shift.isApprox(centre, 1e-13));
  EXPECT_NEAR(p.mass, 7800.0 * (vp + vb), 1e-12 * p.mass);
  const Matrix3d t = tensor_about(cs, centre);
  EXPECT_TRUE((p.frame * p.geometric_inertia.asDiagonal() * p.frame.transpose()).isApprox(t, 1e-10));
  EXPECT_LE(p.inertia[0], p.inertia[1]);
  EXPECT_LE(p.inertia[1], p.inertia[2]);
  // PLANx embedded frame mapped into the body frame (:1219-1224).
  EXPECT_TRUE((p.frame * p.contactor_frames[0]).isApprox(e, 1e-12));
  EXPECT_TRUE(p.contactor_frames[1].isIdentity(0.0));
}

TEST(Rigid3DProperties, GivenInertiaLineOnAClusterIsKeptWithAPlaceholderFrame) {
  // mod_RBDY3.f90:1089-1113: I-line kept, frame identity (DOF.INI expected), shifts not rotated;
  // the centre is still recomputed and the volume is the contactors' even with avrd given.
  const double rho = 2.0, r = 0.01;
  const Vector3d given(3e-9, 2e-9, 1e-9);
  const Vector3d s0(0.03, 0.01, 0.0), s1(-0.01, 0.01, 0.02);
  const auto p = rigid_3d_properties(rho, 0.5, given, {ball(r, s0), ball(r, s1)});
  EXPECT_TRUE(p.geometric_inertia.isApprox(given, 0.0));
  EXPECT_TRUE(p.inertia.isApprox(rho * given, 1e-15));
  EXPECT_TRUE(p.frame.isIdentity(0.0));
  EXPECT_TRUE(p.frame_is_placeholder);
  EXPECT_EQ(p.avrd, 0.5);                                           // a given avrd is kept (:1060)...
  EXPECT_NEAR(p.mass, rho * 2.0 * ball_volume(r), 1e-14 * p.mass);  // ...but V = Σ V_i (:1054)
  const Vector3d centre = 0.5 * (s0 + s1);
  EXPECT_TRUE(p.centre_shift.isApprox(centre, 1e-14));
  EXPECT_TRUE(p.contactor_shifts[0].isApprox(s0 - centre, 1e-13));
  EXPECT_TRUE(p.contactor_shifts[1].isApprox(s1 - centre, 1e-13));
}

TEST(Rigid3DProperties, Pt3dxWeighsNothingInTheCentreButEntersTheInertia) {
  // mod_RBDY3.f90:1044 (vi = 0 for PT3Dx) and :1144 (its volume in the Huygens term).
  const double avrd = 0.01;
  const Vector3d pt(0.0, 0.0, 0.05);
  const auto p =
      rigid_3d_properties(1.0, avrd, Vector3d::Zero(),
                          {sphere(0.02), {"PT3Dx", 0.0, pt, Vector3d::Zero(), Matrix3d::Identity(), {}, {}}});
  EXPECT_TRUE(p.centre_shift.isZero(0.0));
  EXPECT_NEAR(p.volume, ball_volume(0.02), 1e-18);
  const double vpt = ball_volume(avrd);
  const double i_sphere = 0.4 * 0.02 * 0.02 * ball_volume(0.02), i_pt = 0.4 * avrd * avrd * vpt;
  EXPECT_NEAR(p.geometric_inertia[0], i_sphere + i_pt + vpt * 0.05 * 0.05, 1e-20);
  EXPECT_NEAR(p.geometric_inertia[2], i_sphere + i_pt, 1e-20);
}

TEST(Rigid3DProperties, UnmodelledContactorsAreCountedAndDegenerateBodiesRejected) {
  const Rigid3DContactorShape other{"POLYF", 0.01, Vector3d::Zero(), Vector3d::Zero(), Matrix3d::Identity(),
                                    {},      {}};
  const auto p = rigid_3d_properties(1.0, 0.0, Vector3d::Zero(), {sphere(0.01), other});
  EXPECT_EQ(p.ignored_contactors, 1u);
  EXPECT_THROW(rigid_3d_properties(1.0, 0.0, Vector3d::Zero(), {}), std::invalid_argument);
  EXPECT_THROW(rigid_3d_properties(1.0, 0.1, Vector3d::Zero(), {other, other}), std::invalid_argument);
}

// CYLND (mod_a_BDARY_CYLND.f90:84-89): a solid cylinder of half-length H, radius r, axis along the
// localframe's third column, which becomes the body's principal frame.
TEST(Rigid3DProperties, CylinderIsASolidCylinderAlongItsFrameThirdAxis) {
  const double H = 0.3, r = 0.1, density = 2000.0;
  Matrix3d frame;
  frame << 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, -1.0, 0.0, 0.0;  // axis (third column) along x
  const Rigid3DContactorShape cylinder{"CYLND", r, Vector3d(0.1, 0.0, 0.0), Vector3d(0.0, 0.0, H), frame,
                                       {},      {}};
  const auto p = rigid_3d_properties(density, 0.0, Vector3d::Zero(), {cylinder});
  const double V = lmgc_pi * r * r * 2.0 * H;
  EXPECT_NEAR(p.volume, V, 1e-15);
  EXPECT_NEAR(p.mass, density * V, 1e-12);
  EXPECT_NEAR(p.inertia(0), density * V * (r * r / 4.0 + H * H / 3.0), 1e-15);
  EXPECT_NEAR(p.inertia(2), density * V * r * r / 2.0, 1e-15);
  EXPECT_TRUE(p.frame.isApprox(frame));
  EXPECT_TRUE(p.centre_shift.isApprox(Vector3d(0.1, 0.0, 0.0)));
}

TEST(Rigid3DProperties, Diagonalise33ZeroesNoiseRelativeToTheDiagonalAndKeepsTheOrder) {
  Matrix3d t = Vector3d(3.0, 1.0, 2.0).asDiagonal();
  t(0, 1) = t(1, 0) = 1e-15;  // < 1e-14 · diagonal: negligible
  const auto d = lmgc_diagonalise33(t);
  EXPECT_TRUE(d.moments.isApprox(Vector3d(3.0, 1.0, 2.0), 0.0));
  EXPECT_TRUE(d.frame.isIdentity(0.0));
  // Below 1e-10 on the diagonal the threshold is absolute (1e-17).
  Matrix3d small = Vector3d(3e-11, 1e-11, 2e-11).asDiagonal();
  small(0, 2) = small(2, 0) = 5e-18;
  EXPECT_TRUE(lmgc_diagonalise33(small).frame.isIdentity(0.0));
  small(0, 2) = small(2, 0) = 5e-16;
  const auto s = lmgc_diagonalise33(small);
  EXPECT_LT(s.moments[0], s.moments[1]);
  EXPECT_LT(s.moments[1], s.moments[2]);
  EXPECT_NEAR(s.frame.determinant(), 1.0, 1e-12);
}

// --- LMGC90 examples ----------------------------------------------------------------------------

// Minimal fixed-column reader of RBDY3 BODIES.DAT / BODIES.OUT (datbox-inputs.md §1.2, §1.4).
struct ExampleBody {
  std::string behav;
  double avrd = 0.0;
  Vector3d inertia = Vector3d::Zero();
  Vector3d node = Vector3d::Zero();
  std::vector<Rigid3DContactorShape> contactors;
};

double d14(const std::string& line, std::size_t col) {  // value at 1-based columns col..col+13
  if (line.size() < col) return 0.0;
  std::string s = line.substr(col - 1, 14);
  std::replace(s.begin(), s.end(), 'D', 'E');
  std::replace(s.begin(), s.end(), 'd', 'E');
  return std::strtod(s.c_str(), nullptr);
}

Vector3d d14x3(const std::string& line) {
  return {d14(line, 35), d14(line, 56), d14(line, 77)};
}

std::vector<std::string> data_lines(const std::filesystem::path& path) {
  std::istringstream in(test::read_file(path));
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '!' || line.find_first_not_of(' ') == std::string::npos) continue;
    lines.push_back(line);
  }
  return lines;
}

std::vector<ExampleBody> read_rbdy3(const std::filesystem::path& path) {
  const auto lines = data_lines(path);
  std::vector<ExampleBody> bodies;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string& l = lines[i];
    const std::string key = l.substr(1, 5);
    if (key == "bdyty") {
      bodies.emplace_back();
    } else if (bodies.empty()) {
      continue;
    } else if (key == "PLAIN") {
      bodies.back().behav = l.substr(22, 5);
      bodies.back().avrd = d14(l, 35);
      if (i + 1 < lines.size() && lines[i + 1].size() > 31 && lines[i + 1].substr(29, 2) == "I1")
        bodies.back().inertia = d14x3(lines[++i]);
    } else if (key == "NO6xx") {
      bodies.back().node = d14x3(l);
    } else if (key == "SPHER" || key == "SPHEb" || key == "PLANx") {
      Rigid3DContactorShape c{key, 0.0, Vector3d::Zero(), Vector3d::Zero(), Matrix3d::Identity(), {}, {}};
      if (key == "PLANx") {
        c.half_axes = d14x3(l);
        if (i + 1 < lines.size() && lines[i + 1].size() >= 39 &&
            lines[i + 1].substr(29, 10) == "localframe") {
          for (int k = 0; k < 3; ++k) c.frame.col(k) = d14x3(lines[i + 2 + k]);
          c.shift = d14x3(lines[i + 5]);
          i += 5;
        }
      } else {
        c.radius = d14(l, 35);
        if (key == "SPHEb") c.shift = d14x3(lines[++i]);
      }
      bodies.back().contactors.push_back(c);
    }
  }
  return bodies;
}

std::map<std::string, double> read_densities(const std::filesystem::path& path) {
  std::map<std::string, double> rho;
  for (const auto& l : data_lines(path)) {
    const auto at = l.find("Umas=");
    if (l.find("RIGID") == std::string::npos || at == std::string::npos) continue;
    rho[l.substr(1, 5)] = d14(l, at + 6);
  }
  return rho;
}

// |a - b| within the 7 significant digits of a D14.7 field.
void expect_d14_near(double computed, double written, const std::string& what) {
  EXPECT_NEAR(computed, written, 6e-7 * std::abs(written) + 1e-15) << what;
}

struct ExampleCheck {
  std::vector<RigidBody3DProperties> properties;
  std::vector<ExampleBody> input;
};

// Computes every body of `case_dir` and compares with LMGC90's BODIES.OUT echo.
ExampleCheck check_against_bodies_out(const std::filesystem::path& case_dir) {
  const auto input = read_rbdy3(case_dir / "DATBOX" / "BODIES.DAT");
  const auto echo = read_rbdy3(case_dir / "reference_lmgc90" / "OUTBOX" / "BODIES.OUT");
  const auto rho = read_densities(case_dir / "DATBOX" / "BULK_BEHAV.DAT");
  ExampleCheck out;
  out.input = input;
  EXPECT_EQ(input.size(), echo.size());
  for (std::size_t b = 0; b < std::min(input.size(), echo.size()); ++b) {
    const std::string tag = test::case_name(case_dir) + " body " + std::to_string(b + 1);
    const ExampleBody& in = input[b];
    const ExampleBody& lm = echo[b];
    const double density = rho.at(in.behav);
    const auto p = rigid_3d_properties(density, in.avrd, in.inertia, in.contactors);
    out.properties.push_back(p);
    EXPECT_EQ(p.ignored_contactors, 0u) << tag;
    expect_d14_near(p.avrd, lm.avrd, tag + " avrd");
    for (int k = 0; k < 3; ++k) {
      expect_d14_near(p.geometric_inertia[k], lm.inertia[k], tag + " I" + std::to_string(k + 1));
      expect_d14_near(in.node[k] + p.centre_shift[k], lm.node[k], tag + " centre " + std::to_string(k + 1));
    }
    // The written avrd and I-line give the mass and inertia LMGC90's comp_mass builds (:3756-3763):
    // every body here has avrd computed from its volume, so m = Umas 4/3 π avrd³.
    EXPECT_NEAR(p.mass, density * 4.0 / 3.0 * pi * std::pow(lm.avrd, 3.0), 2e-6 * p.mass) << tag;
    EXPECT_NEAR(p.inertia.x(), density * lm.inertia.x(), 1e-6 * p.inertia.x()) << tag;
    EXPECT_EQ(lm.contactors.size(), in.contactors.size()) << tag;
    for (std::size_t c = 0; c < std::min(lm.contactors.size(), p.contactor_shifts.size()); ++c) {
      for (int k = 0; k < 3; ++k)
        expect_d14_near(p.contactor_shifts[c][k], lm.contactors[c].shift[k], tag + " contactor shift");
      if (in.contactors[c].type == "PLANx") {
        EXPECT_TRUE(p.contactor_frames[c].isApprox(lm.contactors[c].frame, 1e-6)) << tag;
      }
    }
  }
  return out;
}

TEST(Rigid3DPropertiesExamples, ClusterSP2PLMatchesBodiesOutEcho) {
  LMGC_REQUIRE_SHARED();
  const auto dir = test::examples_dir() / "RIGID_3D" / "1_ClusterSP_2_PL";
  const auto check = check_against_bodies_out(dir);
  ASSERT_EQ(check.properties.size(), 3u);
  // The cluster (body 3, 4 SPHEb of radius 5 mm, Umas 580): V = 4 · 4/3 π r³, avrd = 0.7937005D-02,
  // centre z = 0.7165064D-02, I = 0.7003134D-10 0.7003134D-10 0.6021386D-10 (diagonal tensor: not
  // sorted, identity frame).
  const auto& cluster = check.properties[2];
  const double v = 4.0 * ball_volume(0.005);
  EXPECT_NEAR(cluster.volume, v, 1e-15 * v);
  EXPECT_NEAR(cluster.mass, 580.0 * v, 1e-15 * 580.0 * v);
  EXPECT_TRUE(cluster.frame.isIdentity(0.0));
  EXPECT_GT(cluster.geometric_inertia[0], cluster.geometric_inertia[2]);
}

TEST(Rigid3DPropertiesExamples, ClusterSP2PLFrameIsConsistentWithDofOut) {
  LMGC_REQUIRE_SHARED();
  const auto dir = test::examples_dir() / "RIGID_3D" / "1_ClusterSP_2_PL";
  // Body 3 is not in DOF.INI, so its initial frame is the computed one (read_in_dof :1543-1563).
  for (const auto& l : data_lines(dir / "DATBOX" / "DOF.INI"))
    if (l.substr(1, 5) == "RBDY3") {
      ASSERT_NE(std::atoi(l.substr(6).c_str()), 3);
    }
  const auto input = read_rbdy3(dir / "DATBOX" / "BODIES.DAT");
  ASSERT_EQ(input.size(), 3u);
  const auto p = rigid_3d_properties(580.0, input[2].avrd, input[2].inertia, input[2].contactors);

  // DOF.OUT.1 (step 10): the cluster spins about its principal axis 2 only (V(5) ≫ V(4), V(6)),
  // so F0ᵀ F10 must be a rotation about e2.
  const auto lines = data_lines(dir / "reference_lmgc90" / "OUTBOX" / "DOF.OUT.1");
  Matrix3d f10 = Matrix3d::Zero();
  Vector3d omega = Vector3d::Zero();
  bool found = false;
  for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
    if (lines[i].substr(1, 5) != "RBDY3" || std::atoi(lines[i].substr(6).c_str()) != 3) continue;
    for (std::size_t j = i + 1; j < lines.size() && lines[j].substr(1, 5) != "bdyty"; ++j) {
      const std::string label = lines[j].size() > 33 ? lines[j].substr(29, 4) : "";
      if (label == "V(4)") omega = d14x3(lines[j]);
      if (label == "a(1)") f10.col(0) = d14x3(lines[j]);
      if (label == "b(1)") f10.col(1) = d14x3(lines[j]);
      if (label == "g(1)") f10.col(2) = d14x3(lines[j]);
    }
    found = true;
    break;
  }
  ASSERT_TRUE(found);
  ASSERT_GT(std::abs(omega.y()), 1e3 * std::max(std::abs(omega.x()), std::abs(omega.z())));
  const Matrix3d r = p.frame.transpose() * f10;
  EXPECT_NEAR(r(1, 1), 1.0, 1e-6);
  EXPECT_NEAR(r(0, 1), 0.0, 1e-6);
  EXPECT_NEAR(r(2, 1), 0.0, 1e-6);
  EXPECT_NEAR(r(1, 0), 0.0, 1e-6);
  EXPECT_NEAR(r(1, 2), 0.0, 1e-6);
  EXPECT_GT(std::abs(r(0, 2)), 0.05);  // it did turn
}

TEST(Rigid3DPropertiesExamples, SpheresAndWallsOf945SPBoxPLMatchBodiesOutEcho) {
  LMGC_REQUIRE_SHARED();
  const auto check = check_against_bodies_out(test::examples_dir() / "RIGID_3D" / "945_SP_Box_PL");
  EXPECT_EQ(check.properties.size(), 950u);
}

}  // namespace
}  // namespace lmgc::solver
