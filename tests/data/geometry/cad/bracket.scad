// L-bracket in mm for tests/unit/geometry/testCadSurfaces.C: a 60 x 40 x 10
// base and a 10 x 40 x 50 upright at x = 0..10, a hole of radius 8 through
// the base along z at (40, 20) and one of radius 6 through the upright
// along x at (y, z) = (20, 35). Holes are 48-gons.
// Volume: 60*40*10 + 10*40*40 - pi*8^2*10 - pi*6^2*10 mm^3.
$fn = 48;
difference()
{
    union()
    {
        cube([60, 40, 10]);
        cube([10, 40, 50]);
    }
    translate([40, 20, -1]) cylinder(r = 8, h = 12);
    translate([-1, 20, 35]) rotate([0, 90, 0]) cylinder(r = 6, h = 12);
}
