# Hollow sphere for tests/unit/geometry/testCadSurfaces.C, written by VTK's
# vtkSTLWriter (binary): an outer sphere of radius 0.5 and an inner one of
# radius 0.3 (a cavity) about the origin, 48 x 24 latitude-longitude
# facets each. Volume 4/3 pi (0.5^3 - 0.3^3) m^3.
# Run: pvpython hollowSphere.py
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkFiltersCore import vtkAppendPolyData
from vtkmodules.vtkIOGeometry import vtkSTLWriter

append = vtkAppendPolyData()
for radius in (0.5, 0.3):
    sphere = vtkSphereSource()
    sphere.SetRadius(radius)
    sphere.SetThetaResolution(48)
    sphere.SetPhiResolution(24)
    sphere.Update()
    append.AddInputData(sphere.GetOutput())
append.Update()

writer = vtkSTLWriter()
writer.SetInputData(append.GetOutput())
writer.SetFileTypeToBinary()
writer.SetFileName("hollowSphere.stl")
writer.Write()
