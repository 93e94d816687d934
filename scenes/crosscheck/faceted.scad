// Small $fn polygons as OpenSCAD means them (--facets auto, the default): a hex nut with a
// round bore, a square peg flush with a cube, an octagonal rod through a block, a faceted
// sphere ($fn=8), a pentagonal cone and a triangular prism, over a floor, two lights.
use <../scadray.scad>

camera(location=[0, -24, 15], look_at=[0, 0, 1.5], fov=50);
point_light(position=[-10, -16, 22]);
point_light(position=[18, -8, 10], color=[0.3, 0.3, 0.3]);
background(color=[0.2, 0.25, 0.35]);

material(color=[0.85, 0.85, 0.8], ambient=0.1, diffuse=0.7) translate([-13, -8, -1]) cube([26, 18, 1]);

// Hex nut: hexagon minus a round bore ($fn=48 stays smooth)
material(color="gold", phong=0.4) translate([-8, 0, 0.01]) difference() {
    cylinder(r=2.4, h=1.8, $fn=6);
    translate([0, 0, -1]) cylinder(r=1.2, h=4, $fn=48);
}

// Square peg standing flush on a cube: coincident faces at z=2
material(color="seagreen") translate([-3, -2, 0.01]) union() {
    cube([3, 3, 2]);
    translate([1.5, 1.5, 2]) cylinder(r=1.2, h=2, $fn=4);
}

// Octagonal rod through a block, cut away
material(color="steelblue", specular=0.3) translate([3.5, 1, 0.01]) difference() {
    cube([3, 3, 3]);
    translate([1.5, 1.5, -1]) cylinder(d=2, h=5, $fn=8);
}

// Faceted sphere, pentagonal cone, triangular prism
material(color="tomato", phong=0.5) translate([-5, 5, 2]) sphere(r=2, $fn=8);
material(color="orchid") translate([9, -2, 0.01]) cylinder(r1=1.8, r2=0, h=3.5, $fn=5);
material(color="darkorange") translate([1, 6, 0.01]) rotate([0, 0, 15]) cylinder(r=1.5, h=2.5, $fn=3);
