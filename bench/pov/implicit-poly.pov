// Generated from scenes/implicit.toml by bench/toml_to_pov.py. Do not edit.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb <1, 1, 1> max_trace_level 6 adc_bailout 1/1024 }
camera { location <0, 3.2, -6.5> sky <0, 1, 0> look_at <0, 0.75, 0>
         right x * image_width / image_height angle 65.810435 }

background { rgb <0.45, 0.55, 0.75> }
light_source { <-5, 8, -6> color rgb <0.8, 0.8, 0.8> }
light_source { <6, 4, -3> color rgb <0.3, 0.3, 0.35> }

polygon { 5, <-6, 0, -6>, <6, 0, -6>, <6, 0, 6>, <-6, 0, 6>, <-6, 0, -6>
  pigment { checker rgb <0.95, 0.95, 0.95>, rgb <0.3, 0.32, 0.36> scale 0.5 }
  finish { ambient 0.09 diffuse 0.72 phong 0 phong_size 40 reflection 0.1 }
  
}

polynomial { 2,
  xyz(2, 0, 0): 0.01,
  xyz(0, 2, 0): 0.01,
  xyz(0, 0, 2): 0.01,
  xyz(0, 0, 0): -0.81000000000000005
  sturm
  clipped_by { box { <-10, -10, -10>, <10, 10, 10> } }
  bounded_by { clipped_by }
  scale 0.1
  pigment { rgb <0.2, 0.35, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.6 phong_size 50 reflection 0 }
  translate <-1.6, 0.9, 0.4>
}

polynomial { 4,
  xyz(4, 0, 0): 0.0001,
  xyz(2, 2, 0): 0.00020000000000000001,
  xyz(2, 0, 2): 0.00020000000000000001,
  xyz(2, 0, 0): -0.022450000000000001,
  xyz(0, 4, 0): 0.0001,
  xyz(0, 2, 2): 0.00020000000000000001,
  xyz(0, 2, 0): 0.017550000000000003,
  xyz(0, 0, 4): 0.0001,
  xyz(0, 0, 2): -0.022450000000000001,
  xyz(0, 0, 0): 0.77000625000000011
  sturm
  clipped_by { box { <-14, -4, -14>, <14, 4, 14> } }
  bounded_by { clipped_by }
  scale 0.1
  pigment { rgb <0.9, 0.65, 0.2> }
  finish { ambient 0.075 diffuse 0.45 phong 0.6 phong_size 60 reflection 0.25 }
  rotate <-30, 0, 0> translate <1.2, 0.95, 0>
}

