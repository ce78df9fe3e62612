// The twin of bench/photons.toml for POV-Ray 3.7's photon mapping, written by hand
// (bench/toml_to_pov.py refuses refraction). The same camera, ball, floor and spot light:
//   - angle: lancer's vertical fov 30 at 4:3 is a horizontal angle of 39.320 degrees;
//   - the light: lancer's 12 W spread over the spot's weighted cone (0.21502 sr) is
//     55.809 W/sr, whose colour in lancer's units is 55.809 / pi = 17.7646 at 1 m. POV-Ray's
//     fade_power 2 gives colour * 2 / (1 + (d / D)^2); with D = 0.01 that is colour * 2 D^2 / d^2
//     within 1e-5 beyond 1 m, so the colour is 17.7646 / (2 D^2) = 88823: inverse-square
//     fall-off as lancer's. (An earlier D = 1/sqrt(2) gave 1 / (d^2 + 0.5): the floor 2% dark.)
//   - glass: transmit 1, exact Fresnel reflection, ior 1.5, no diffuse or ambient, as lancer's
//     transmission = 1 with diffuse 0; the floor: diffuse 1, no ambient.
// The photons. POV-Ray shoots them at the ball on a grid of directions; its default jitter 0.4
// leaves that grid in the caustic as moire, jitter 1 stratifies it. Its default gather (20 to
// 100 nearest photons, the radius chosen from the photon spacing) keeps the number of photons
// per estimate about constant whatever the count, so more photons give a sharper picture but
// never a less noisy one; here the gather radius is fixed (RADIUS, 0.015, where the long
// references of the two renderers agree best), never widened where it finds no photon (gather
// minimum 0: widening cost POV-Ray a second per render at small counts, for the same picture),
// and up to 20,000 photons are summed, so the estimate converges as photons are added, as
// lancer's progressive one does. max_trace_level 3
// for photons: light, glass, glass, floor (and light, glass, floor), the paths bench/photons.toml
// keeps with max_bounces = 3 (POV-Ray has no global photon map; lancer's would add the light
// the floor sends back down through the ball).
// PHOTONS (POV-Ray's `count`: about 2.2 times the photons it then shoots at the ball) and RADIUS
// are set by bench/photons.sh (Declare=... on the command line).
#version 3.7;
#ifndef (PHOTONS) #declare PHOTONS = 100000; #end
#ifndef (RADIUS) #declare RADIUS = 0.015; #end
global_settings {
  assumed_gamma 1.0
  ambient_light rgb 0
  max_trace_level 7
  adc_bailout 1/1024
  photons { count PHOTONS radius RADIUS gather 0, 20000 jitter 1 max_trace_level 3 }
}
camera { location <-1.9, 3.4, -1.3> sky <0, 1, 0> look_at <-0.45, 0, 0.15>
         right x * image_width / image_height angle 39.320 }
background { rgb 0 }
light_source { <1.5, 5, -0.5> color rgb 88823
  spotlight point_at <0, 1.2, 0> radius 14 falloff 16 tightness 0
  fade_distance 0.01 fade_power 2
  photons { refraction on reflection on }
}
plane { y, 0
  pigment { rgb 0.9 }
  finish { ambient 0 diffuse 1 }
}
sphere { <0, 1.2, 0>, 0.7
  material {
    texture { pigment { rgbt 1 } finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel on } conserve_energy } }
    interior { ior 1.5 }
  }
  photons { target refraction on reflection on collect off }
}
