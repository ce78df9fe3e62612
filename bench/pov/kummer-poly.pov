// Generated from scenes/kummer.toml by bench/toml_to_pov.py. Do not edit.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb <1, 1, 1> max_trace_level 6 adc_bailout 1/1024 }
camera { location <0, 3.6, -7.5> sky <0, 1, 0> look_at <0, 1.5, 0>
         right x * image_width / image_height angle 65.810435 }

background { rgb <0.45, 0.55, 0.75> }
light_source { <-5, 8, -6> color rgb <0.8, 0.8, 0.8> }
light_source { <6, 4, -3> color rgb <0.3, 0.3, 0.35> }

polygon { 5, <-6, 0, -6>, <6, 0, -6>, <6, 0, 6>, <-6, 0, 6>, <-6, 0, -6>
  pigment { checker rgb <0.95, 0.95, 0.95>, rgb <0.3, 0.32, 0.36> scale 0.5 }
  finish { ambient 0.09 diffuse 0.72 phong 0 phong_size 40 reflection 0.1 }
  
}

polynomial { 4,
  xyz(4, 0, 0): 0.0001,
  xyz(2, 2, 0): -0.00048191013879087284,
  xyz(2, 0, 2): 0.00054095506939543642,
  xyz(2, 0, 1): 0.0068191013879087261,
  xyz(2, 0, 0): 0.0081035069395436338,
  xyz(0, 4, 0): 0.0001,
  xyz(0, 2, 2): 0.00054095506939543642,
  xyz(0, 2, 1): -0.0068191013879087261,
  xyz(0, 2, 0): 0.0081035069395436338,
  xyz(0, 0, 4): -7.0477534697718146e-05,
  xyz(0, 0, 2): 0.0081035069395436303,
  xyz(0, 0, 0): -0.01581518697718165
  sturm
  clipped_by { box { <-22, -22, -22>, <22, 22, 22> } }
  bounded_by { clipped_by }
  scale 0.1
  pigment { rgb <0.3, 0.75, 0.55> }
  finish { ambient 0.1 diffuse 0.65 phong 0.6 phong_size 50 reflection 0 }
  scale 0.65 rotate <-60, 25, 0> translate <0, 1.5, 0>
}

