// SPDX-License-Identifier: MIT
// scadray's ray-tracing metadata as pass-through modules: OpenSCAD ignores them (camera,
// lights and settings produce nothing, material() passes its children through), while
// scadray reads their arguments. Load with `use <scadray.scad>`. The defaults below are
// scadray's own; colours accept anything color() does: names, "#rrggbb", [r, g, b].

// Perspective camera. location and look_at are points, sky is the up direction; all three are
// moved by the transforms around the call. fov is the HORIZONTAL full angle in degrees
// (POV-Ray's `angle`). The first camera() of a scene is used.
module camera(location=[0,-10,5], look_at=[0,0,0], sky=[0,0,1], fov=40) {}

// Point light at `position` (moved by the enclosing transforms). color is its intensity per
// channel. With fade_distance and fade_power both > 0 the light falls off as POV-Ray's
// 2 / (1 + (d / fade_distance)^fade_power); shadowless lights cast no shadows and no highlights.
module point_light(position=[10,-10,10], color=[1,1,1], fade_distance=0, fade_power=0, shadowless=false) {}

// POV-Ray area light: a point light whose shadows average an n1 x n2 grid of shadow rays
// spanning axis1 x axis2 about `position` (samples = [n1, n2]); colour, fade and highlights come
// from the centre, as in POV-Ray. The grid is averaged recursively as POV-Ray does: adaptive is
// its level (0 to 100; 100 = every grid point). jitter moves each grid point by up to half a
// cell, drawn from the pixel sample's seeded stream, so the penumbra converges with more
// samples per pixel (POV-Ray's jitter does the same from its own table). circular maps the
// grid onto a disc; orient turns it to face each shaded point (and makes it circular).
module area_light(position=[10,-10,10], axis1=[1,0,0], axis2=[0,1,0], samples=[5,5], color=[1,1,1], adaptive=100, jitter=false, circular=false, orient=false, fade_distance=0, fade_power=0) {}

// Surface and interior of the children (POV-Ray 3.7 pigment, finish and interior).
// color: pigment used when no color() encloses the object (color() wins; its alpha < 1 sets
//   transmit = 1 - alpha). filter / transmit: fractions of light passing through, tinted / not.
// ambient, diffuse, brilliance, phong, phong_size, specular, roughness, metallic: classic
//   local illumination. reflection: a number (min = max) or [min, max], between 0 and 1;
//   reflection_falloff, reflection_exponent and fresnel shape it; conserve_energy as POV-Ray.
// emission: a number or [r, g, b] of light the surface gives off.
// ior: index of refraction of the interior; fade_distance, fade_power and fade_color attenuate
//   light travelling through it. The innermost material() around an object applies.
// glossy / frosted (scadray only; POV-Ray 3.7 shows them sharp): the angular spread, in degrees
//   (standard deviation), of reflected / refracted rays about the sharp direction. Where a path
//   first meets such a surface it sends blur_samples rays over the lobe, later ones one ray;
//   blur_lobe is "normal" (normally distributed angle) or "phong" (cosine-power lobe
//   cos^n with n = 1/spread^2, spread in radians).
module material(color=undef, filter=0, transmit=0, ambient=0.15, diffuse=0.75, brilliance=1, phong=0, phong_size=40, specular=0, roughness=0.05, metallic=0, reflection=0, reflection_falloff=1, reflection_exponent=1, fresnel=false, conserve_energy=false, emission=0, ior=1, fade_distance=0, fade_power=0, fade_color=[0,0,0], glossy=0, frosted=0, blur_samples=8, blur_lobe="normal") children();

// Colour seen where rays leave the scene.
module background(color=[0,0,0]) {}

// Global settings: maximum ray recursion depth, the contribution below which secondary rays
// stop (adc_bailout), and the multiplier of every finish's ambient term (ambient_light).
module render_settings(max_trace_level=5, adc_bailout=1/255, ambient_light=[1,1,1]) {}
