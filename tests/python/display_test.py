"""DISPLAY/ of a run with deformable bodies, opened by VTK's own reader (Debian's python3-vtk9), not
by string matching: reference_cases/mailx_patch_q4 run by lmgc-run with display calls added to its
script gives meshes_1.vtu with the mesh (16 nodes, 9 quads), its displacements (those of DOF.LAST,
the affine field A x) and the uniform stress of the patch at every node; lmgc90.pvd lists it."""
import os
import shutil
import subprocess
import tempfile
import unittest
import xml.etree.ElementTree as ElementTree

SOURCE = os.environ["LMGC_SOURCE_DIR"]
TOOLS = os.environ["LMGC_TOOLS"]

try:
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError:  # pragma: no cover - the test is skipped without VTK
    vtk = None


@unittest.skipIf(vtk is None, "python3-vtk9 is not installed")
class MeshDisplay(unittest.TestCase):
    def test_the_patch_mesh_opens_in_vtk_with_its_fields(self):
        work = tempfile.mkdtemp(prefix="lmgc_display_")
        case = os.path.join(SOURCE, "reference_cases", "mailx_patch_q4")
        shutil.copytree(os.path.join(case, "DATBOX"), os.path.join(work, "DATBOX"))
        with open(os.path.join(case, "command.py")) as f:
            script = f.read()
        script = script.replace("chipy.ComputeMass()", "chipy.OpenDisplayFiles()\nchipy.ComputeMass()", 1)
        script = script.replace("  chipy.WriteOut(freq_write)", "  chipy.WriteOut(freq_write)\n  chipy.WriteDisplayFiles(1)")
        with open(os.path.join(work, "command.py"), "w") as f:
            f.write(script)
        run = subprocess.run([os.path.join(TOOLS, "lmgc-run"), work, "--quiet"], capture_output=True, text=True)
        self.assertEqual(run.returncode, 0, run.stderr)
        reader = vtk.vtkXMLUnstructuredGridReader()
        reader.SetFileName(os.path.join(work, "DISPLAY", "meshes_1.vtu"))
        reader.Update()
        grid = reader.GetOutput()
        self.assertEqual(grid.GetNumberOfPoints(), 16)
        self.assertEqual(grid.GetNumberOfCells(), 9)
        self.assertTrue(all(grid.GetCellType(i) == vtk.VTK_QUAD for i in range(9)))
        disp = vtk_to_numpy(grid.GetPointData().GetArray("Disp"))
        stress = vtk_to_numpy(grid.GetPointData().GetArray("S"))
        ids = vtk_to_numpy(grid.GetPointData().GetArray("Node Id"))
        points = vtk_to_numpy(grid.GetPoints().GetData())
        a = [[1e-3, 2e-3], [-0.5e-3, 1.5e-3]]
        for p in range(16):
            reference = points[p, :2] - disp[p, :2]
            for c in range(2):
                self.assertAlmostEqual(disp[p, c], a[c][0] * reference[0] + a[c][1] * reference[1], delta=1e-9)
            # σ (xx, xy, zz) entries of the 3 × 3 tensor: the patch's uniform stress.
            self.assertAlmostEqual(stress[p, 0] / 1.8e6, 1.0, delta=1e-5)
            self.assertAlmostEqual(stress[p, 1] / 0.6e6, 1.0, delta=1e-5)
            self.assertAlmostEqual(stress[p, 4] / 2.2e6, 1.0, delta=1e-5)
            self.assertAlmostEqual(stress[p, 8] / 1.0e6, 1.0, delta=1e-5)
        self.assertEqual(sorted(ids), list(range(1, 17)))
        collection = ElementTree.parse(os.path.join(work, "DISPLAY", "lmgc90.pvd")).getroot()
        files = [d.get("file") for d in collection.iter("DataSet")]
        self.assertIn("meshes_1.vtu", files)
        shutil.rmtree(work)


if __name__ == "__main__":
    unittest.main()
