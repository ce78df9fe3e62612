// Generated from scenes/seed.toml by bench/toml_to_pov.py. Do not edit.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb <1, 1, 1> max_trace_level 6 adc_bailout 1/1024 }
camera { location <0, 3.2, -9> sky <0, 1, 0> look_at <0, 0.9, 0>
         right x * image_width / image_height angle 72.7343514 }

background { rgb <0.42, 0.56, 0.78> }
light_source { <-6, 10, -7> color rgb <0.75, 0.75, 0.75> }
light_source { <8, 7, -4> color rgb <0.45, 0.45, 0.45> }

polygon { 5, <-6, 0, -5>, <6, 0, -5>, <6, 0, 7>, <-6, 0, 7>, <-6, 0, -5>
  pigment { checker rgb <1, 1, 1>, rgb <0.42, 0.42, 0.42> scale 1 }
  finish { ambient 0.1104 diffuse 0.736 phong 0 phong_size 40 reflection 0.08 }
  
}

sphere { <0, 1.3, 1>, 1.3
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0 diffuse 0.005 phong 0.09 phong_size 200 reflection 0.9 }
  
}

sphere { <-2.6, 0.8, -0.6>, 0.8
  pigment { rgb <0.85, 0.08, 0.06> }
  finish { ambient 0.1 diffuse 0.7 phong 0.6 phong_size 40 reflection 0 }
  
}

sphere { <2.4, 1, -0.2>, 1
  pigment { rgb <0.1, 0.2, 0.85> }
  finish { ambient 0.085 diffuse 0.595 phong 0.595 phong_size 80 reflection 0.15 }
  
}

sphere { <-1, 0.5, -2.4>, 0.5
  pigment { rgb <0.1, 0.65, 0.15> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 30 reflection 0 }
  
}

sphere { <1.3, 0.45, -2.8>, 0.45
  pigment { rgb <0.9, 0.75, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.4 phong_size 20 reflection 0 }
  
}

