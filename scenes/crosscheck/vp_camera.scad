// OpenSCAD's viewport variables as the camera ($vpt, $vpr, $vpd, $vpf), with explicit lights.
use <../scadray.scad>

$vpt = [0, 0, 2];
$vpr = [65, 0, 30];
$vpd = 30;
$vpf = 30;
point_light(position=[-10, -15, 25]);
point_light(position=[15, -5, 10], color=[0.3, 0.3, 0.3], shadowless=true);
background(color=[0.9, 0.9, 0.85]);

material(color=[0.7, 0.72, 0.75], ambient=0.15) translate([-8, -8, -1]) cube([16, 16, 1]);
material(color="darkcyan", phong=0.5) rotate([0, 0, 20]) difference() {
    cube([6, 6, 4], center=true);
    sphere(r=3.7, $fn=64);
}
