// POV-Ray's classic finish terms one at a time: ambient only, diffuse, brilliance, phong,
// specular with roughness, and metallic-tinted highlights; ambient_light tints the ambient.
use <../scadray.scad>

camera(location=[0, -20, 6], look_at=[0, 0, 1.5], fov=55);
point_light(position=[-6, -14, 14]);
background(color=[0.05, 0.05, 0.08]);
render_settings(ambient_light=[0.8, 0.9, 1]);

material(color=[0.7, 0.7, 0.72], ambient=0.1, diffuse=0.6) translate([-14, -6, -1]) cube([28, 14, 1]);

c = [0.9, 0.35, 0.2];
translate([-10, 0, 1.5]) material(color=c, ambient=0.7, diffuse=0) sphere(r=1.5, $fn=48);
translate([-6, 0, 1.5]) material(color=c, ambient=0.05, diffuse=0.9) sphere(r=1.5, $fn=48);
translate([-2, 0, 1.5]) material(color=c, ambient=0.05, diffuse=0.9, brilliance=4) sphere(r=1.5, $fn=48);
translate([2, 0, 1.5]) material(color=c, ambient=0.05, diffuse=0.7, phong=0.8, phong_size=25) sphere(r=1.5, $fn=48);
translate([6, 0, 1.5]) material(color=c, ambient=0.05, diffuse=0.7, specular=0.7, roughness=0.02) sphere(r=1.5, $fn=48);
translate([10, 0, 1.5]) material(color=c, ambient=0.05, diffuse=0.6, phong=0.9, phong_size=80, specular=0.5, roughness=0.01, metallic=1) sphere(r=1.5, $fn=48);
