// Benchmark (scripts/bench_vs_openscad.sh): a plate with 16 bores rounded by a Minkowski sum
// with a sphere: the plate is not convex, so it is summed as itself moved plus a hull of the
// sphere with each convex piece of its boundary.
minkowski() {
    difference() {
        cube([40, 40, 3]);
        for (x = [5:10:35], y = [5:10:35]) translate([x, y, -1]) cylinder(r=2, h=5, $fn=16);
    }
    sphere(1, $fn=12);
}
