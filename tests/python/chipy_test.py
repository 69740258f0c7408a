"""lmgc.chipy from Python: LMGC90's signatures, numpy getters, and bad use turned into clear
exceptions (never a crash); a script that raises mid-run leaves whole files. Run by ctest with the
build's python/ folder on PYTHONPATH and the tools folder in LMGC_TOOLS."""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import numpy as np

SOURCE = os.environ["LMGC_SOURCE_DIR"]
TOOLS = os.environ["LMGC_TOOLS"]
PUSHER = os.path.join(SOURCE, "reference_cases", "script_driven_pusher")


def case_copy():
    work = tempfile.mkdtemp(prefix="lmgc_chipy_")
    shutil.copytree(os.path.join(PUSHER, "DATBOX"), os.path.join(work, "DATBOX"))
    return work


class ChipyCalls(unittest.TestCase):
    def setUp(self):
        from lmgc import chipy
        self.chipy = chipy
        self.work = case_copy()
        self.cwd = os.getcwd()
        os.chdir(self.work)
        chipy._configure(max_steps=-1, quiet=True)
        chipy.Initialize()
        chipy.checkDirectories()
        chipy.SetDimension(2)
        chipy.TimeEvolution_SetTimeStep(1e-3)
        chipy.Integrator_InitTheta(0.5)
        chipy.ReadDatbox(deformable=False)

    def tearDown(self):
        self.chipy.Finalize()
        os.chdir(self.cwd)
        shutil.rmtree(self.work)

    def step(self):
        c = self.chipy
        c.IncrementStep()
        c.ComputeFext()
        c.ComputeBulk()
        c.ComputeFreeVelocity()
        c.SelectProxTactors()
        c.RecupRloc()
        c.ExSolver('Stored_Delassus_Loops         ', 'Quad ', 1e-10, 1.0, 50, 100)
        c.UpdateTactBehav()
        c.StockRloc()
        c.ComputeDof()
        c.UpdateStep()

    def test_getters_are_numpy_arrays_with_lmgc90s_shapes(self):
        c = self.chipy
        self.assertEqual(c.RBDY2_GetNbRBDY2(), 6)
        self.assertEqual(c.RBDY3_GetNbRBDY3(), 0)
        v = c.RBDY2_GetBodyVector('Coor_', 3)
        self.assertIsInstance(v, np.ndarray)
        self.assertEqual(v.shape, (3,))
        np.testing.assert_allclose(v, [-0.25, 0.1, 0.0])
        all_coor = c.RBDY2_GetAllBodyVector('Coor0')
        self.assertEqual(all_coor.shape, (6, 3))
        # One copy: the array owns its buffer; writing into it does not change the bodies.
        v[0] = 99.0
        self.assertEqual(c.RBDY2_GetBodyVector('Coor_', 3)[0], -0.25)

    def test_contactor_tables_and_equilibrium(self):
        c = self.chipy
        self.assertEqual(c.DISKx_GetNbDISKx(), 5)
        self.assertEqual(c.JONCx_GetNbJONCx(), 1)
        np.testing.assert_array_equal(c.DISKx_GetPtrDISKx2BDYTY()[:, 0], [2, 3, 4, 5, 6])
        self.assertEqual(c.DKJCx_ID, 4)
        c.RBDY2_SetEquilibriumNorm('Qvlcy', 1e-6)
        self.assertTrue(c.RBDY2_CheckEquilibriumState())  # every body at rest
        c.RBDY2_PutBodyVector('Vbeg_', 6, [0.0, 1.0, 0.0])
        self.assertFalse(c.RBDY2_CheckEquilibriumState())

    def test_interactions_after_a_step(self):
        self.step()
        inters = self.chipy.getInteractions()
        self.assertGreaterEqual(len(inters), 4)  # three disks and the small one on the floor, at least
        self.assertIn('DKJCx', set(inters['inter']))
        self.assertEqual(inters['uc'].shape[1:], (2, 2))
        floor = inters[inters['inter'] == 'DKJCx']
        self.assertTrue(np.all(floor['ianbdy'] == 1))
        self.assertEqual(np.count_nonzero(floor['rl'][:, 1] > 0.0), 4)  # the floor carries the four free disks
        np.testing.assert_allclose(floor['uc'][:, :, 1], np.tile([0.0, 1.0], (len(floor), 1)))  # n up
        np.testing.assert_allclose(floor['uc'][:, :, 0], np.tile([1.0, 0.0], (len(floor), 1)))  # t = (n_y, -n_x)
        c = self.chipy
        self.assertEqual(c.inter_handler_2D_getNb(c.DKJCx_ID), len(floor))
        rows = c.inter_handler_2D_getAll(c.DKJCx_ID)
        self.assertEqual(rows.shape, (len(floor), 11))
        np.testing.assert_allclose(rows[:, 6:8], floor['rl'])

    def test_wrong_counts_and_types_raise(self):
        c = self.chipy
        with self.assertRaises(TypeError):
            c.RBDY2_GetBodyVector('Coor_')
        with self.assertRaises(TypeError):
            c.TimeEvolution_SetTimeStep()
        with self.assertRaises(ValueError):
            c.TimeEvolution_SetTimeStep('fast')
        with self.assertRaises(ValueError):
            c.RBDY2_PutBodyVector('Vbeg_', 6, [1.0, 2.0])
        with self.assertRaises(IndexError):
            c.RBDY2_GetBodyVector('V____', 7)
        with self.assertRaises(ValueError):
            c.RBDY2_GetBodyVector('Speed', 1)

    def test_calls_out_of_order_raise_runtime_errors(self):
        c = self.chipy
        with self.assertRaisesRegex(RuntimeError, "twice"):
            c.ReadBodies()
        with self.assertRaisesRegex(RuntimeError, "before IncrementStep"):
            c.ComputeDof()
        c.IncrementStep()
        c.ComputeFext()
        c.ComputeFreeVelocity()
        with self.assertRaisesRegex(RuntimeError, "ExSolver before .*SelectProxTactors"):
            c.ExSolver('Stored_Delassus_Loops', 'Quad ', 1e-4, 1.0, 10, 10)

    def test_an_unknown_call_names_itself(self):
        with self.assertRaisesRegex(NotImplementedError, "RBDY2_FatalDamping"):
            self.chipy.RBDY2_FatalDamping()
        with self.assertRaisesRegex(NotImplementedError, "chipy.Frobnicate"):
            self.chipy.Frobnicate(1)
        self.assertIn('RBDY2_FatalDamping', self.chipy.__all__)


class Documented(unittest.TestCase):
    def test_every_call_lmgc_offers_is_in_docs_chipy_md(self):
        import re
        from lmgc import chipy
        doc = open(os.path.join(SOURCE, "docs", "chipy.md")).read()
        named = set(re.findall(r"`(\w+)\(", doc))
        offered = [n for n in chipy.__all__
                   if callable(getattr(chipy, n)) and not getattr(getattr(chipy, n), "lmgc_missing", False)]
        self.assertGreater(len(offered), 80)
        self.assertEqual(sorted(set(offered) - named), [])


class MeshInteractions(unittest.TestCase):
    """getInteractions on a case with contact on a mesh: its bodies' types and numbers as LMGC90 gives
    them (reference_cases/mailx_hertz_cylinder: CLxxx points of MAILx 1 on the JONCx of RBDY2 1)."""

    def test_mesh_contacts_name_their_mailx_and_rigid_bodies(self):
        from lmgc import chipy
        work = tempfile.mkdtemp(prefix="lmgc_chipy_mesh_")
        shutil.copytree(os.path.join(SOURCE, "reference_cases", "mailx_hertz_cylinder", "DATBOX"),
                        os.path.join(work, "DATBOX"))
        cwd = os.getcwd()
        os.chdir(work)
        try:
            chipy._configure(max_steps=-1, quiet=True)
            chipy.Initialize()
            chipy.checkDirectories()
            chipy.SetDimension(2, 1)
            chipy.TimeEvolution_SetTimeStep(0.005)
            chipy.Integrator_InitTheta(1.0)
            chipy.ReadDatbox(deformable=True)
            chipy.ComputeMass()
            chipy.ComputeBulk()
            for _ in range(3):
                for call in ("IncrementStep", "ComputeFext", "ComputeBulk", "AssembleMechanicalRHS",
                             "AssembleMechanicalLHS", "ComputeFreeVelocity", "SelectProxTactors", "RecupRloc"):
                    getattr(chipy, call)()
                chipy.ExSolver('Stored_Delassus_Loops         ', 'Quad ', 1e-6, 1.0, 50, 100)
                for call in ("UpdateTactBehav", "StockRloc", "ComputeDof", "UpdateStep"):
                    getattr(chipy, call)()
            inters = chipy.getInteractions()
            self.assertGreater(len(inters), 0)
            self.assertEqual(chipy.inter_handler_2D_getNb(chipy.CLJCx_ID), len(inters))
            for i in inters:
                self.assertEqual((i[0], i[2], i[3], i[4], i[5], i[6], i[7], i[9]),
                                 ('CLJCx', 'MAILx', 'RBDY2', 1, 1, 'CLxxx', 'JONCx', 1))
            self.assertTrue(all(1 <= i[8] <= 62 for i in inters))
            chipy.Finalize()
        finally:
            os.chdir(cwd)
            shutil.rmtree(work)

    def test_a_mesh_free_to_move_without_mass_stops_the_script_naming_it(self):
        from lmgc import chipy
        work = tempfile.mkdtemp(prefix="lmgc_chipy_massless_")
        shutil.copytree(os.path.join(SOURCE, "reference_cases", "mailx_glued_blocks", "DATBOX"),
                        os.path.join(work, "DATBOX"))
        bulk = os.path.join(work, "DATBOX", "BULK_BEHAV.DAT")
        text = open(bulk).read().replace("Umas= 0.1000000D+04", "Umas= 0.0000000D+00")
        open(bulk, "w").write(text)
        cwd = os.getcwd()
        os.chdir(work)
        try:
            chipy._configure(max_steps=-1, quiet=True)
            chipy.Initialize()
            chipy.checkDirectories()
            chipy.SetDimension(2, 1)
            chipy.TimeEvolution_SetTimeStep(1e-3)
            chipy.Integrator_InitTheta(0.5)
            chipy.ReadDatbox(deformable=True)
            chipy.ComputeMass()
            chipy.ComputeBulk()
            for call in ("IncrementStep", "ComputeFext", "ComputeBulk", "AssembleMechanicalRHS"):
                getattr(chipy, call)()
            with self.assertRaisesRegex(RuntimeError, "MAILx body 2: its iteration matrix"):
                chipy.ComputeFreeVelocity()
            chipy.Finalize()
        finally:
            os.chdir(cwd)
            shutil.rmtree(work)


class ScriptRuns(unittest.TestCase):
    def run_script(self, body, *args):
        work = case_copy()
        with open(os.path.join(work, "command.py"), "w") as f:
            f.write(body)
        run = subprocess.run([os.path.join(TOOLS, "lmgc-run"), work, "--quiet"] + list(args),
                             capture_output=True, text=True)
        return work, run

    HEAD = ("from pylmgc90 import chipy\nimport sys\nchipy.Initialize()\nchipy.checkDirectories()\n"
            "chipy.SetDimension(2)\nchipy.TimeEvolution_SetTimeStep(1e-3)\nchipy.ReadDatbox(deformable=False)\n"
            "chipy.OpenPostproFiles()\n")
    LOOP = ("for k in range(NB):\n  chipy.IncrementStep()\n  chipy.ComputeFext()\n  chipy.ComputeFreeVelocity()\n"
            "  chipy.SelectProxTactors()\n  chipy.RecupRloc()\n"
            "  chipy.ExSolver('Stored_Delassus_Loops', 'Quad ', 1e-8, 1.0, 50, 100)\n  chipy.UpdateTactBehav()\n"
            "  chipy.StockRloc()\n  chipy.ComputeDof()\n  chipy.UpdateStep()\n  chipy.WriteOutDof(2)\n"
            "  chipy.WritePostproFiles()\n")

    def test_a_script_that_raises_leaves_whole_files(self):
        work, run = self.run_script(self.HEAD + self.LOOP.replace("NB", "5") + "raise RuntimeError('user stop')\n")
        self.assertEqual(run.returncode, 1, run.stderr)
        self.assertIn("user stop", run.stderr)
        report = open(os.path.join(work, "OUTBOX", "run_report.csv")).read()
        self.assertTrue(report.endswith("\n"))
        self.assertEqual(report.count("\n"), 6)  # header and five steps
        self.assertTrue(os.path.exists(os.path.join(work, "OUTBOX", "DOF.OUT.2")))
        shutil.rmtree(work)

    def test_max_steps_ends_the_script_with_its_last_files(self):
        work, run = self.run_script(self.HEAD + self.LOOP.replace("NB", "1000"), "--max-steps", "7")
        self.assertEqual(run.returncode, 0, run.stderr)
        dof = open(os.path.join(work, "OUTBOX", "DOF.LAST")).read()
        self.assertRegex(dof, r"\$steps +7 ")
        shutil.rmtree(work)

    def test_script_arguments_reach_sys_argv(self):
        body = self.HEAD + "assert sys.argv[1:] == ['--norand', 'x'], sys.argv\n"
        work, run = self.run_script(body, "--", "--norand", "x")
        self.assertEqual(run.returncode, 0, run.stderr)
        shutil.rmtree(work)

    def test_star_import_of_pylmgc90_chipy_runs_a_script(self):
        body = ("from pylmgc90.chipy import *\nInitialize()\ncheckDirectories()\nSetDimension(2)\n"
                "TimeEvolution_SetTimeStep(1e-3)\nReadDatbox(deformable=False)\nfor k in range(3):\n"
                "  IncrementStep(); ComputeFext(); ComputeFreeVelocity(); SelectProxTactors(); RecupRloc()\n"
                "  ExSolver('Stored_Delassus_Loops', 'Quad ', 1e-8, 1.0, 50, 100); UpdateTactBehav(); StockRloc()\n"
                "  ComputeDof(); UpdateStep()\nassert TimeEvolution_GetStep() == 3\nWriteLastDof()\nFinalize()\n")
        work, run = self.run_script(body)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertTrue(os.path.exists(os.path.join(work, "OUTBOX", "DOF.LAST")))
        shutil.rmtree(work)

    def test_a_call_lmgc_does_not_offer_stops_the_script_with_its_name(self):
        work, run = self.run_script(self.HEAD + "chipy.RBDY2_FatalDamping()\n")
        self.assertEqual(run.returncode, 1)
        self.assertIn("NotImplementedError: chipy.RBDY2_FatalDamping", run.stderr)
        shutil.rmtree(work)


if __name__ == "__main__":
    unittest.main()
