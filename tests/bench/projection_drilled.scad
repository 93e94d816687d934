// Benchmark (scripts/bench_vs_openscad.sh): the shadow of a finely faceted ball drilled twice,
// seen at an angle (5,000 sphere faces, each cut to the part on the result's boundary), and
// its section, extruded into plates.
module drilled() rotate([30, 20, 0]) difference() {
    sphere(10, $fn=100);
    cylinder(r=3, h=30, center=true, $fn=60);
    rotate([90, 0, 0]) cylinder(r=2, h=30, center=true, $fn=60);
}
linear_extrude(1) projection() drilled();
translate([25, 0, 0]) linear_extrude(1) projection(cut=true) drilled();
