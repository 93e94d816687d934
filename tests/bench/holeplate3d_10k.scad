// Benchmark (scripts/bench_csg.sh generates it at other sizes): a 100 x 100 x 2 plate
// with 10,000 round holes of radius 0.3 on a 1 mm grid, as difference() of a cube and 10,000
// translated cylinders: the CSG difference finds the holes a ray meets through a BVH.
// Run: build/tools/scadray render tests/bench/holeplate3d_10k.scad -W 640 -H 480
difference() {
    cube([100, 100, 2]);
    for (i = [0 : 99], j = [0 : 99]) translate([i + 0.5, j + 0.5, -1]) cylinder(r=0.3, h=4);
}
