// The chipy session checks a script's calls as they come: out of order, twice, an unknown body or
// dof, a vector of the wrong name or size each raise an Error of their kind (the Python module
// maps the kinds to exceptions), never a crash. What the calls do: a script's step is lmgc's step,
// PutBodyVector and SetVlocyDrivenDof change the state as LMGC90's do, --max-steps ends the run
// with its .LAST files.
#include "chipy/session.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>

#include "tests/support/run_tool.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::chipy {
namespace {

namespace fs = std::filesystem;

fs::path pusher_copy(const std::string& name) {
  const fs::path dir = test::scratch_dir(name);
  fs::copy(fs::path(LMGC_SOURCE_DIR) / "reference_cases" / "script_driven_pusher" / "DATBOX", dir / "DATBOX",
           fs::copy_options::recursive);
  return dir;
}

void read_all(Session& s) {
  for (int r = 0; r < static_cast<int>(Reading::count); ++r) s.read(static_cast<Reading>(r));
}

void set_up(Session& s) {
  s.set_dimension(2, 1);
  s.set_time_step(1e-3);
  s.init_theta(0.5);
  read_all(s);
}

void step(Session& s) {
  s.stage("IncrementStep");
  s.stage("ComputeFext");
  s.stage("ComputeBulk");
  s.stage("ComputeFreeVelocity");
  s.select_prox_tactors(1, 0, 0);
  s.recup_rloc(std::nullopt);
  s.ex_solver("Stored_Delassus_Loops", "Quad ", 1e-10, 1.0, 50, 100);
  s.stage("UpdateTactBehav");
  s.stage("StockRloc");
  s.stage("ComputeDof");
  s.stage("UpdateStep");
}

ErrorKind kind_of(const std::function<void()>& call) {
  try {
    call();
  } catch (const Error& e) {
    return e.kind;
  }
  ADD_FAILURE() << "no error";
  return ErrorKind::output;
}

TEST(ChipySession, CallsOutOfOrderRaiseAnOrderError) {
  Session s(pusher_copy("chipy_order"), {});
  EXPECT_EQ(kind_of([&] { s.read(Reading::bodies); }), ErrorKind::order);  // before SetDimension
  set_up(s);
  EXPECT_EQ(kind_of([&] { s.read(Reading::bodies); }), ErrorKind::order);  // twice
  EXPECT_EQ(kind_of([&] { s.stage("ComputeFext"); }), ErrorKind::order);   // before IncrementStep
  s.stage("IncrementStep");
  // ExSolver before SelectProxTactors.
  EXPECT_EQ(kind_of([&] { s.ex_solver("Stored_Delassus_Loops", "Quad ", 1e-4, 1.0, 10, 10); }),
            ErrorKind::order);
  s.stage("ComputeFext");
  EXPECT_EQ(kind_of([&] { s.stage("ComputeFext"); }), ErrorKind::order);  // twice in a step
  s.stage("ComputeFreeVelocity");
  EXPECT_EQ(kind_of([&] { s.stage("IncrementStep"); }), ErrorKind::order);  // before UpdateStep
  EXPECT_EQ(kind_of([&] { s.stage("UpdateStep"); }), ErrorKind::order);     // before ComputeDof
  s.select_prox_tactors(1, 0, 0);
  s.recup_rloc(std::nullopt);
  s.ex_solver("Stored_Delassus_Loops", "Quad ", 1e-10, 1.0, 50, 100);
  EXPECT_EQ(kind_of([&] { s.stage("ComputeFext"); }), ErrorKind::order);  // after what needs it
  s.stage("UpdateTactBehav");
  s.stage("StockRloc");
  s.stage("ComputeDof");
  s.stage("UpdateStep");
  EXPECT_EQ(s.steps_done(), 1);
  EXPECT_EQ(s.step(), 1);
}

TEST(ChipySession, BadArgumentsRaiseTheirKind) {
  Session s(pusher_copy("chipy_arguments"), {});
  EXPECT_EQ(kind_of([&] { s.set_dimension(4, 1); }), ErrorKind::value);
  EXPECT_EQ(kind_of([&] { s.set_time_step(-1.0); }), ErrorKind::value);
  EXPECT_EQ(kind_of([&] { s.init_theta(0.2); }), ErrorKind::value);
  set_up(s);
  EXPECT_EQ(s.body_count(2), 6u);
  EXPECT_EQ(kind_of([&] { s.body_vector(2, "V____", 7); }), ErrorKind::index);
  EXPECT_EQ(kind_of([&] { s.body_vector(2, "V____", 0); }), ErrorKind::index);
  EXPECT_EQ(kind_of([&] { s.body_vector(2, "Vxxxx", 1); }), ErrorKind::value);
  EXPECT_EQ(kind_of([&] { s.body_vector(2, "Vaux_", 1); }), ErrorKind::not_implemented);
  const std::vector<double> two{1.0, 2.0};
  EXPECT_EQ(kind_of([&] { s.put_body_vector(2, "Vbeg_", 6, two); }), ErrorKind::value);
  const std::vector<double> nan{0.0, std::nan(""), 0.0};
  EXPECT_EQ(kind_of([&] { s.put_body_vector(2, "Vbeg_", 6, nan); }), ErrorKind::value);
  EXPECT_EQ(kind_of([&] { s.body_vector(3, "V____", 1); }), ErrorKind::order);  // RBDY3 call, 2D case
  s.stage("IncrementStep");
  EXPECT_EQ(kind_of([&] { s.set_vlocy_driven_dof(2, 3, 1, 0.1); }), ErrorKind::value);  // not driven
  EXPECT_EQ(kind_of([&] { s.set_vlocy_driven_dof(2, 2, 4, 0.1); }), ErrorKind::index);
  EXPECT_EQ(kind_of([&] { s.select_prox_tactors(2, 0, 0); }), ErrorKind::not_implemented);
  s.stage("ComputeFext");
  s.stage("ComputeFreeVelocity");
  s.select_prox_tactors(1, 0, 0);
  s.recup_rloc(std::nullopt);
  EXPECT_EQ(kind_of([&] { s.ex_solver("Stored_Delassus_Loops", "Quux ", 1e-4, 1.0, 10, 10); }),
            ErrorKind::value);
  EXPECT_EQ(kind_of([&] { s.ex_solver("Stored_Delassus_Loops", "Quad ", 1e-4, 3.0, 10, 10); }),
            ErrorKind::value);
}

TEST(ChipySession, PutBodyVectorAndDrivenVelocitiesMoveTheBodies) {
  Session s(pusher_copy("chipy_put"), {});
  set_up(s);
  step(s);
  // A kick between steps: the next step starts from it (free flight under gravity).
  const std::vector<double> kick{0.0, 1.0, 0.0};
  s.put_body_vector(2, "Vbeg_", 6, kick);
  const double y0 = s.body_vector(2, "Coor_", 6)[1];
  s.stage("IncrementStep");
  s.set_vlocy_driven_dof(2, 2, 1, 0.5);  // the pusher's x velocity for this step
  s.stage("ComputeFext");
  s.stage("ComputeFreeVelocity");
  s.select_prox_tactors(1, 0, 0);
  s.recup_rloc(std::nullopt);
  s.ex_solver("Stored_Delassus_Loops", "Quad ", 1e-10, 1.0, 50, 100);
  s.stage("UpdateTactBehav");
  s.stage("StockRloc");
  s.stage("ComputeDof");
  s.stage("UpdateStep");
  const double h = 1e-3, g = 9.81;
  const std::vector<double> v6 = s.body_vector(2, "V____", 6);
  EXPECT_NEAR(v6[1], 1.0 - g * h, 1e-12);
  EXPECT_NEAR(s.body_vector(2, "Coor_", 6)[1] - y0, h * (1.0 + v6[1]) / 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.body_vector(2, "V____", 2)[0], 0.5);
  EXPECT_NEAR(s.body_vector(2, "X____", 2)[0], h * 0.5 / 2.0, 1e-15);             // θ = ½ from rest
  EXPECT_NEAR(s.body_mass(2, 6), 1000.0 * std::numbers::pi * 0.05 * 0.05, 1e-6);  // LMGC90's π: 7 digits
}

TEST(ChipySession, MaxStepsEndsTheRunWithItsLastFiles) {
  const fs::path dir = pusher_copy("chipy_max_steps");
  Session s(dir, SessionOptions{3, true});
  set_up(s);
  for (int k = 0; k < 3; ++k) step(s);
  EXPECT_EQ(kind_of([&] { s.stage("IncrementStep"); }), ErrorKind::step_limit);
  EXPECT_TRUE(fs::exists(dir / "OUTBOX" / "DOF.LAST"));
  EXPECT_TRUE(fs::exists(dir / "OUTBOX" / "Vloc_Rloc.LAST"));
  EXPECT_EQ(s.step(), 3);
}

TEST(ChipySession, AnInvalidCaseRaisesWithItsDiagnostics) {
  const fs::path dir = pusher_copy("chipy_invalid");
  std::ofstream(dir / "DATBOX" / "BULK_BEHAV.DAT") << "$gravy\n nonsense\n";
  Session s(dir, SessionOptions{-1, true});
  s.set_dimension(2, 1);
  try {
    s.read(Reading::behaviours);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind, ErrorKind::data);
    EXPECT_NE(std::string(e.what()).find("DATBOX/BODIES.DAT:5:23: error[L2001]"), std::string::npos)
        << e.what();
  }
  // The wrong dimension.
  Session t(pusher_copy("chipy_dimension"), SessionOptions{-1, true});
  t.set_dimension(3, 1);
  EXPECT_EQ(kind_of([&] { t.read(Reading::bodies); }), ErrorKind::data);
}

// A deformable case through the session alone (no Python; the sanitizer build runs it): the patch
// of reference_cases/mailx_patch_q4 writes LMGC90's DOF.LAST and GPV.LAST byte for byte; Rayleigh
// damping asked before ComputeMass is built without its mass part, as LMGC90 builds it.
TEST(ChipySession, AMeshPatchWritesLmgc90sFiles) {
  const fs::path source = fs::path(LMGC_SOURCE_DIR) / "reference_cases" / "mailx_patch_q4";
  const fs::path dir = test::scratch_dir("chipy_mailx_patch");
  fs::copy(source / "DATBOX", dir / "DATBOX", fs::copy_options::recursive);
  Session s(dir, SessionOptions{-1, true});
  s.set_dimension(2, 1);
  s.set_time_step(1.0);
  s.init_theta(1.0);
  read_all(s);
  EXPECT_TRUE(s.has_deformable_bodies());
  s.compute_mass();
  s.stage("ComputeBulk");  // before the loop, as LMGC90's linear scripts call it
  s.stage("IncrementStep");
  s.stage("ComputeFext");
  s.stage("ComputeBulk");
  s.stage("ComputeFreeVelocity");
  s.select_prox_tactors(1, 0, 0);
  s.recup_rloc(std::nullopt);
  s.ex_solver("Stored_Delassus_Loops", "Quad ", 1e-4, 1.0, 10, 10);
  s.stage("UpdateTactBehav");
  s.stage("StockRloc");
  s.stage("ComputeDof");
  s.stage("UpdateStep");
  s.write_last_dof();
  s.write_last_gpv();
  s.finalize();
  for (const char* file : {"DOF.LAST", "GPV.LAST"})
    EXPECT_TRUE(test::read_file(dir / "OUTBOX" / file) == test::read_file(source / "lmgc90_reference" / file))
        << file;
  EXPECT_FALSE(fs::exists(dir / "OUTBOX" / "EXACT_STATE.LAST"));  // not written beside meshes
}

TEST(ChipySession, MeshCasesNeedTheirHypothesis) {
  const fs::path dir = test::scratch_dir("chipy_mailx_mode");
  fs::copy(fs::path(LMGC_SOURCE_DIR) / "reference_cases" / "mailx_patch_q4" / "DATBOX", dir / "DATBOX",
           fs::copy_options::recursive);
  Session s(dir, SessionOptions{-1, true});
  EXPECT_EQ(kind_of([&] { s.set_dimension(2, 4); }), ErrorKind::value);  // LMGC90 stops on mod 4
  s.set_dimension(2, 3);                                                 // axisymmetric
  read_all(s);
  EXPECT_TRUE(s.has_deformable_bodies());
}

}  // namespace
}  // namespace lmgc::chipy
