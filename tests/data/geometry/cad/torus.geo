// Torus about z through the origin for tests/unit/geometry/testCadSurfaces.C:
// major radius 0.3, minor radius 0.1 (m), OpenCASCADE kernel, binary STL.
// Volume 2 pi^2 R r^2; its cut by z = 0 is the annulus 0.2 < r < 0.4.
SetFactory("OpenCASCADE");
Torus(1) = {0, 0, 0, 0.3, 0.1};
Mesh.MeshSizeFromCurvature = 28;   // elements per 2 pi of curvature
Mesh.MeshSizeMax = 0.05;
Mesh.Binary = 1;
Mesh 2;
Save "torus.stl";
