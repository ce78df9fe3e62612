// Generated from scenes/clebsch.toml by bench/toml_to_pov.py. Do not edit.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb <1, 1, 1> max_trace_level 6 adc_bailout 1/1024 }
camera { location <0, 3.6, -7> sky <0, 1, 0> look_at <0, 1.4, 0>
         right x * image_width / image_height angle 65.810435 }

background { rgb <0.45, 0.55, 0.75> }
light_source { <-5, 8, -6> color rgb <0.8, 0.8, 0.8> }
light_source { <6, 4, -3> color rgb <0.3, 0.3, 0.35> }

polygon { 5, <-6, 0, -6>, <6, 0, -6>, <6, 0, 6>, <-6, 0, 6>, <-6, 0, -6>
  pigment { checker rgb <0.95, 0.95, 0.95>, rgb <0.3, 0.32, 0.36> scale 0.5 }
  finish { ambient 0.09 diffuse 0.72 phong 0 phong_size 40 reflection 0.1 }
  
}

polynomial { 3,
  xyz(3, 0, 0): 0.081000000000000003,
  xyz(2, 1, 0): -0.189,
  xyz(2, 0, 1): -0.189,
  xyz(2, 0, 0): -0.089999999999999997,
  xyz(1, 2, 0): -0.189,
  xyz(1, 1, 1): 0.053999999999999999,
  xyz(1, 1, 0): 1.26,
  xyz(1, 0, 2): -0.189,
  xyz(1, 0, 1): 1.26,
  xyz(1, 0, 0): -0.90000000000000002,
  xyz(0, 3, 0): 0.081000000000000003,
  xyz(0, 2, 1): -0.189,
  xyz(0, 2, 0): -0.089999999999999997,
  xyz(0, 1, 2): -0.189,
  xyz(0, 1, 1): 1.26,
  xyz(0, 1, 0): -0.90000000000000002,
  xyz(0, 0, 3): 0.081000000000000003,
  xyz(0, 0, 2): -0.089999999999999997,
  xyz(0, 0, 1): -0.90000000000000002,
  xyz(0, 0, 0): 1
  sturm
  clipped_by { box { <-10, -10, -10>, <10, 10, 10> } }
  bounded_by { clipped_by }
  scale 0.1
  pigment { rgb <0.95, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.65 phong 0.6 phong_size 50 reflection 0 }
  scale 1.3 rotate <-15, 40, 0> translate <0, 1.4, 0>
}

