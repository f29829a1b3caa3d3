#!/usr/bin/env python3
# Read a .vtu file with VTK's own reader (as ParaView does) and print what
# it contains: "points N", "cells N", "polygon cells N", and one line per data
# array with its range. Exits non-zero if the file cannot be read or an
# expected array is missing.
#   read_vtu.py FILE                 a file of write_vtu_file (small strain)
#   read_vtu.py FILE finite-strain   a file of write_finite_strain_vtu_file:
#     the finite-strain fields as point and cell data, and no small-strain
#     "stress" or "von_mises" (an unexpected array counts as missing)
import sys
import vtk

reader = vtk.vtkXMLUnstructuredGridReader()
reader.SetFileName(sys.argv[1])
reader.Update()
grid = reader.GetOutput()
if grid is None or grid.GetNumberOfPoints() == 0:
    print("cannot read", sys.argv[1])
    sys.exit(1)
print("points", grid.GetNumberOfPoints())
print("cells", grid.GetNumberOfCells())
polygons = sum(1 for i in range(grid.GetNumberOfCells()) if grid.GetCellType(i) == vtk.VTK_POLYGON)
print("polygon cells", polygons)
missing = []
finite_strain = len(sys.argv) > 2 and sys.argv[2] == "finite-strain"
if finite_strain:
    fields = ["cauchy_stress", "cauchy_stress_zz", "cauchy_von_mises", "det_F", "principal_stretches"]
    expected = ((grid.GetPointData(), ["displacement"] + fields),
                (grid.GetCellData(), fields + ["body_id", "cell_id"]))
    for data in (grid.GetPointData(), grid.GetCellData()):
        for name in ("stress", "von_mises"):
            if data.GetArray(name) is not None:
                missing.append("(unexpected) " + name)
else:
    expected = ((grid.GetPointData(), ["displacement", "stress", "von_mises"]),
                (grid.GetCellData(), ["stress", "von_mises", "body_id", "cell_id"]))
for data, names in expected:
    for name in names:
        array = data.GetArray(name)
        if array is None:
            missing.append(name)
            continue
        lo, hi = array.GetRange(-1 if array.GetNumberOfComponents() > 1 else 0)
        print("cell array" if data is grid.GetCellData() and finite_strain else "array", name,
              array.GetNumberOfComponents(), lo, hi)
# further point arrays (write_vtu_file's point_data)
for i in range(grid.GetPointData().GetNumberOfArrays()):
    array = grid.GetPointData().GetArray(i)
    if array.GetName() not in [n for n in expected[0][1]]:
        lo, hi = array.GetRange(0)
        print("extra point array", array.GetName(), array.GetNumberOfComponents(), lo, hi)
if missing:
    print("missing arrays:", missing)
    sys.exit(1)
