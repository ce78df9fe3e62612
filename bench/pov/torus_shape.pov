// Generated from bench/torus_shape.toml by bench/toml_to_pov.py. Do not edit.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb <1, 1, 1> max_trace_level 6 adc_bailout 1/1024 }
camera { location <0, 3.2, -5.5> sky <0, 1, 0> look_at <0, 0.55, 0>
         right x * image_width / image_height angle 65.810435 }

background { rgb <0.45, 0.55, 0.75> }
light_source { <-5, 8, -6> color rgb <0.8, 0.8, 0.8> }
light_source { <6, 4, -3> color rgb <0.3, 0.3, 0.35> }

polygon { 5, <-5, 0, -5>, <5, 0, -5>, <5, 0, 5>, <-5, 0, 5>, <-5, 0, -5>
  pigment { checker rgb <0.95, 0.95, 0.95>, rgb <0.3, 0.32, 0.36> scale 0.5 }
  finish { ambient 0.09 diffuse 0.72 phong 0 phong_size 40 reflection 0.1 }
  
}

torus { 1, 0.35 matrix <1, -0, 0, 0, 1, 0, -0, 0, 1, 0, 0, 0>
  pigment { rgb <0.9, 0.65, 0.2> }
  finish { ambient 0.075 diffuse 0.45 phong 0.6 phong_size 60 reflection 0.25 }
  rotate <-30, 0, 0> translate <0, 0.85, 0>
}

