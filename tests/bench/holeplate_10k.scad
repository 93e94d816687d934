// Benchmark (scripts/bench_vs_openscad.sh): a 100 x 100 plate, 2 thick, with 10,000 round holes
// of radius 0.3 on a 1 mm grid, as linear_extrude of a square minus 10,000 circles.
linear_extrude(2) difference() {
    square(100);
    for (i = [0 : 99], j = [0 : 99]) translate([i + 0.5, j + 0.5]) circle(r=0.3, $fn=16);
}
