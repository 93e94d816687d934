// SPDX-License-Identifier: MIT
// An animation for `scadray render --frames N`: the camera circles a CSG part ($vpr follows
// $t) while a ball hops around it the other way (its place follows $t).
$vpr = [65, 0, 360 * $t];
$vpt = [0, 0, 4];
$vpd = 110;

color("silver") difference() {
    cube([30, 30, 10], center = true);
    sphere(r = 9, $fn = 48);
    for (a = [0, 90])
        rotate([0, 0, a]) translate([15, 0, 0]) cylinder(r = 4, h = 20, center = true, $fn = 32);
    translate([-15, -15, 5]) cube([12, 12, 8], center = true);
}
color("tomato")
    translate([22 * cos(-360 * $t), 22 * sin(-360 * $t), 9 + 8 * abs(sin(720 * $t))])
        sphere(r = 4, $fn = 32);
