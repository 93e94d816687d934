// Every scadray metadata module with every parameter named (checked against OpenSCAD too).
use <scadray.scad>
camera(location=[1,-8,4], look_at=[0,0,1], sky=[0,0,1], fov=50);
point_light(position=[5,-5,8], color="white", fade_distance=10, fade_power=2, shadowless=false);
background(color=[0.1,0.1,0.2]);
render_settings(max_trace_level=8, adc_bailout=0.01, ambient_light=[0.5,0.5,0.5]);
material(color="red", filter=0, transmit=0.1, ambient=0.1, diffuse=0.7, brilliance=1, phong=0.5, phong_size=60, specular=0, roughness=0.05, metallic=0, reflection=[0,0.3], reflection_falloff=1, reflection_exponent=1, fresnel=true, conserve_energy=true, emission=0, ior=1.5, fade_distance=1, fade_power=2, fade_color=[0,0,1]) sphere(1);
