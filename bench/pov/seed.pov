// scenes/seed.toml for POV-Ray 3.7, for bench/: the same camera, lights, materials and geometry.
// POV-Ray is left-handed like lancer, so coordinates are unchanged. lancer mixes reflection as
// (1 - r) * local + r * reflected while POV adds r * reflected to the local colour, so every
// finish's ambient, diffuse and phong below are lancer's multiplied by (1 - r).
// Render: povray +Iseed.pov +W1280 +H720 +A0.0 +AM1 +R3 -J +WT2 -D
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 6 adc_bailout 1/1024 }

// vertical fov 45 degrees at 16:9 -> horizontal angle 2 atan(tan(22.5) * 16/9)
camera { location <0, 3.2, -9> look_at <0, 0.9, 0> right x * image_width / image_height
         angle 2 * degrees(atan(tan(radians(22.5)) * image_width / image_height)) }
background { rgb <0.42, 0.56, 0.78> }

light_source { <-6, 10, -7> color rgb 0.75 }
light_source { <8, 7, -4> color rgb 0.45 }

#macro Finish(A, D, S, N, R)
  finish { ambient A * (1 - R) diffuse D * (1 - R) phong S * (1 - R) phong_size N reflection R }
#end

polygon { 5, <-6, 0, -5>, <6, 0, -5>, <6, 0, 7>, <-6, 0, 7>, <-6, 0, -5>
  pigment { checker rgb 1, rgb 0.42 } Finish(0.12, 0.8, 0, 40, 0.08) }
sphere { <0, 1.3, 1>, 1.3 pigment { rgb <0.9, 0.9, 0.9> } Finish(0.0, 0.05, 0.9, 200, 0.9) }
sphere { <-2.6, 0.8, -0.6>, 0.8 pigment { rgb <0.85, 0.08, 0.06> } Finish(0.1, 0.7, 0.6, 40, 0) }
sphere { <2.4, 1, -0.2>, 1 pigment { rgb <0.1, 0.2, 0.85> } Finish(0.1, 0.7, 0.7, 80, 0.15) }
sphere { <-1, 0.5, -2.4>, 0.5 pigment { rgb <0.1, 0.65, 0.15> } Finish(0.1, 0.7, 0.5, 30, 0) }
sphere { <1.3, 0.45, -2.8>, 0.45 pigment { rgb <0.9, 0.75, 0.1> } Finish(0.1, 0.7, 0.4, 20, 0) }
