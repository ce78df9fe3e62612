// The twin of bench/photons.toml for POV-Ray 3.7's photon mapping, written by hand
// (bench/toml_to_pov.py refuses refraction). The same camera, ball, floor and spot light:
//   - angle: lancer's vertical fov 30 at 4:3 is a horizontal angle of 39.320 degrees;
//   - the light: lancer's 12 W spread over the spot's weighted cone (0.21502 sr) is
//     55.809 W/sr, whose colour in lancer's units is 55.809 / pi = 17.7646 at 1 m; POV-Ray's
//     fade_power 2 with fade_distance 1/sqrt(2) gives 2 / (1 + 2 d^2), within 2% of 1 / d^2
//     beyond 4 m (the floor is 4.2 to 5.5 m from the lamp);
//   - glass: transmit 1, exact Fresnel reflection, ior 1.5, no diffuse or ambient, as lancer's
//     transmission = 1 with diffuse 0; the floor: diffuse 1, no ambient.
// PHOTONS is the photon count, set by bench/photons.sh (+D... on the command line).
#version 3.7;
#ifndef (PHOTONS) #declare PHOTONS = 100000; #end
global_settings {
  assumed_gamma 1.0
  ambient_light rgb 0
  max_trace_level 7
  adc_bailout 1/1024
  photons { count PHOTONS gather 20, 100 }
}
camera { location <-1.9, 3.4, -1.3> sky <0, 1, 0> look_at <-0.45, 0, 0.15>
         right x * image_width / image_height angle 39.320 }
background { rgb 0 }
light_source { <1.5, 5, -0.5> color rgb 17.7646
  spotlight point_at <0, 1.2, 0> radius 14 falloff 16 tightness 0
  fade_distance 0.70711 fade_power 2
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
