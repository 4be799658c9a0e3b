# Reads tendril's VTK (legacy and XML) and glTF files of the hanging mass
# (tests/cli/saved_hanging_mass.lua, exported by `tendril export --vtk --glb`)
# with VTK's own readers, as ParaView does, and checks the fields and their
# values against statics. Exit 77 (skipped) when VTK's Python (Debian's
# python3-vtk9) is not installed.
import math
import sys

try:
    import vtk
except ImportError:
    print("VTK's Python is not installed (Debian: python3-vtk9); skipped")
    sys.exit(77)


def check(reader, path):
    """The hanging mass's grid as VTK reads it: fields and statics."""
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    assert grid.GetNumberOfPoints() == 3, grid.GetNumberOfPoints()
    assert grid.GetNumberOfCells() == 2, grid.GetNumberOfCells()
    cells = grid.GetCellData()
    names = {cells.GetArrayName(i) for i in range(cells.GetNumberOfArrays())}
    wanted = {"block", "axial", "strain", "slack", "My", "Mz", "torsion", "moment", "curvature",
              "warp", "weft", "shear", "s1", "s2", "d1", "d2"}
    assert wanted <= names, wanted - names
    # A 1 kg mass between two pins 2 m apart: each cable carries m g / (2 sin theta).
    mass = grid.GetPoint(2)
    sin_theta = -mass[2] / math.hypot(1, mass[2])
    expected = 9.81 / (2 * sin_theta)
    for c in range(2):
        axial = cells.GetArray("axial").GetValue(c)
        assert abs(axial - expected) < 1e-4 * expected, (axial, expected)
        assert grid.GetCellType(c) == vtk.VTK_LINE
    reaction = grid.GetPointData().GetArray("reaction").GetTuple3(0)
    assert abs(reaction[2] - 9.81 / 2) < 1e-4, reaction
    assert grid.GetPointData().GetArray("locked").GetValue(0) == 1
    print("%s: VTK reads %d points, %d cells; N = %.4f N (statics %.4f N); reaction %.4f N" %
          (path, grid.GetNumberOfPoints(), grid.GetNumberOfCells(), cells.GetArray("axial").GetValue(0), expected,
           reaction[2]))
    return mass


legacy = vtk.vtkUnstructuredGridReader()
legacy.ReadAllScalarsOn()
legacy.ReadAllVectorsOn()
mass = check(legacy, sys.argv[1])
check(vtk.vtkXMLUnstructuredGridReader(), sys.argv[3])  # the same grid as VTK XML (.vtu)
check(vtk.vtkXMLPolyDataReader(), sys.argv[4])  # and as VTK XML poly data (.vtp)

# The glTF: one polydata of two line segments (4 vertices), coloured, y up.
gltf = vtk.vtkGLTFReader()
gltf.SetFileName(sys.argv[2])
gltf.Update()
it = gltf.GetOutput().NewIterator()
it.InitTraversal()
leaf = it.GetCurrentDataObject()
assert leaf.GetNumberOfPoints() == 4 and leaf.GetNumberOfLines() == 2, (leaf.GetNumberOfPoints(), leaf.GetNumberOfLines())
assert leaf.GetPointData().GetArray("COLOR_0") is not None
assert abs(leaf.GetPoint(1)[1] - mass[2]) < 1e-6, (leaf.GetPoint(1), mass)  # y up: tendril's z
print("glTF reads %d vertices, %d lines" % (leaf.GetNumberOfPoints(), leaf.GetNumberOfLines()))
