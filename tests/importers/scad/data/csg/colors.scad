// color(): names, hex, vectors, alpha and the outermost-wins rule.
color("red") cube(1);
translate([2, 0, 0]) color("DarkOliveGreen") cube(1);
translate([4, 0, 0]) color("#ff8000") cube(1);
translate([6, 0, 0]) color("#f80") cube(1);
translate([8, 0, 0]) color("#ff000080") cube(1);
translate([10, 0, 0]) color([0.2, 0.4, 0.6]) cube(1);
translate([12, 0, 0]) color([0.2, 0.4, 0.6, 0.5]) cube(1);
translate([14, 0, 0]) color("blue", 0.25) cube(1);
translate([16, 0, 0]) color("red") color("blue") cube(1);
translate([18, 0, 0]) color("nosuchcolor") color("green") cube(1);
translate([20, 0, 0]) color([0.5]) cube(1);
translate([22, 0, 0]) color("transparent") cube(1);
translate([24, 0, 0]) difference() { color("yellow") cube(2); color("purple") sphere(1); }
translate([26, 0, 0]) { color("orange") cube(1); sphere(0.5); }
