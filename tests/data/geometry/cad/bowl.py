# Bowl for tests/unit/geometry/testCadSurfaces.C, a FreeCAD Part solid
# exported through Mesh (binary STL): a 40 x 40 x 20 mm box minus a sphere
# of radius 15 mm centred on the middle of its top face (a hemispherical
# bowl). Volume 40*40*20 - 2/3 pi 15^3 mm^3.
# Run: freecadcmd bowl.py
import FreeCAD
import Part
import Mesh
import MeshPart

box = Part.makeBox(40, 40, 20)
ball = Part.makeSphere(15, FreeCAD.Vector(20, 20, 20))
bowl = box.cut(ball)

# The chord deviation sets the tessellation of the bowl (0.05 mm: a few
# thousand triangles).
mesh = MeshPart.meshFromShape(Shape=bowl, LinearDeflection=0.05,
                              AngularDeflection=0.2, Relative=False)
mesh.write("bowl.stl")
