// Generated from scenes/many.toml by bench/toml_to_pov.py. Do not edit.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb <1, 1, 1> max_trace_level 6 adc_bailout 1/1024 }
camera { location <0, 6, -16> sky <0, 1, 0> look_at <0, 3, 0>
         right x * image_width / image_height angle 79.3168785 }

background { rgb <0.35, 0.45, 0.65> }
light_source { <-10, 18, -12> color rgb <0.8, 0.8, 0.8> }
light_source { <12, 10, -8> color rgb <0.35, 0.35, 0.4> }

plane { <0, 1, 0>, 0
  pigment { checker rgb <0.95, 0.95, 0.95>, rgb <0.3, 0.3, 0.32> scale 1 }
  finish { ambient 0.085 diffuse 0.68 phong 0 phong_size 40 reflection 0.15 }
  
}

sphere { <-4.417, 0.634, -4.62>, 0.215
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.6, 0.696, -3.519>, 0.202
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.541, 0.598, -2.589>, 0.247
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.411, 0.537, -1.446>, 0.255
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.512, 0.643, -0.525>, 0.269
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.421, 0.607, 0.565>, 0.257
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.355, 0.535, 1.56>, 0.191
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.564, 0.5, 2.594>, 0.244
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.563, 0.656, 3.514>, 0.199
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.536, 0.697, 4.418>, 0.216
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.381, 1.324, -4.562>, 0.226
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.471, 1.244, -3.365>, 0.275
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.607, 1.28, -2.628>, 0.209
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.377, 1.224, -1.588>, 0.268
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.379, 1.217, -0.422>, 0.249
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.38, 1.23, 0.372>, 0.203
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.56, 1.21, 1.629>, 0.26
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.482, 1.268, 2.4>, 0.229
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.537, 1.254, 3.357>, 0.21
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.637, 1.19, 4.381>, 0.2
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.62, 1.827, -4.57>, 0.201
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.619, 1.842, -3.634>, 0.196
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.473, 1.834, -2.503>, 0.252
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.569, 1.803, -1.644>, 0.255
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.58, 1.834, -0.571>, 0.232
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.454, 1.97, 0.648>, 0.226
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.383, 1.935, 1.371>, 0.25
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.435, 1.844, 2.477>, 0.267
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.586, 1.964, 3.452>, 0.181
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.639, 1.9, 4.492>, 0.267
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.432, 2.588, -4.421>, 0.2
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.547, 2.501, -3.529>, 0.212
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.52, 2.493, -2.608>, 0.254
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.564, 2.603, -1.403>, 0.225
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.373, 2.545, -0.571>, 0.266
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.546, 2.558, 0.507>, 0.189
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.606, 2.546, 1.482>, 0.231
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.438, 2.639, 2.591>, 0.257
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.647, 2.512, 3.561>, 0.188
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.451, 2.553, 4.414>, 0.217
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.512, 3.101, -4.462>, 0.262
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.516, 3.138, -3.39>, 0.255
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.632, 3.153, -2.422>, 0.183
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.512, 3.23, -1.584>, 0.23
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.578, 3.227, -0.459>, 0.243
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.612, 3.275, 0.412>, 0.223
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.365, 3.163, 1.432>, 0.199
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.488, 3.187, 2.502>, 0.279
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.378, 3.131, 3.459>, 0.271
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.512, 3.231, 4.555>, 0.189
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.55, 3.898, -4.544>, 0.186
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.45, 3.833, -3.594>, 0.234
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.614, 3.887, -2.539>, 0.217
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.478, 3.824, -1.58>, 0.256
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.37, 3.899, -0.511>, 0.23
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.481, 3.895, 0.361>, 0.193
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.463, 3.813, 1.396>, 0.183
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.535, 3.793, 2.566>, 0.205
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.354, 3.845, 3.367>, 0.198
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.563, 3.786, 4.603>, 0.252
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.52, 4.512, -4.467>, 0.266
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.416, 4.441, -3.537>, 0.188
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.408, 4.558, -2.539>, 0.254
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.54, 4.504, -1.361>, 0.256
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.473, 4.565, -0.479>, 0.24
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.527, 4.568, 0.504>, 0.279
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.46, 4.566, 1.522>, 0.259
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.597, 4.503, 2.45>, 0.272
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.483, 4.503, 3.405>, 0.199
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.422, 4.563, 4.379>, 0.191
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.604, 5.159, -4.442>, 0.242
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.358, 5.058, -3.381>, 0.234
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.612, 5.093, -2.462>, 0.197
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.43, 5.072, -1.583>, 0.253
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.5, 5.096, -0.485>, 0.214
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.511, 5.051, 0.45>, 0.209
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.515, 5.188, 1.365>, 0.234
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.461, 5.239, 2.542>, 0.277
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.441, 5.134, 3.408>, 0.267
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.442, 5.105, 4.403>, 0.197
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.434, 5.714, -4.611>, 0.231
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.611, 5.813, -3.434>, 0.247
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.453, 5.826, -2.552>, 0.224
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.446, 5.787, -1.617>, 0.276
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.375, 5.709, -0.638>, 0.256
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.484, 5.716, 0.383>, 0.216
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.512, 5.725, 1.351>, 0.215
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.596, 5.797, 2.624>, 0.209
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.39, 5.716, 3.354>, 0.248
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.516, 5.701, 4.434>, 0.208
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.523, 6.403, -4.425>, 0.276
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.492, 6.51, -3.58>, 0.275
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.561, 6.539, -2.391>, 0.19
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.614, 6.526, -1.49>, 0.214
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.377, 6.507, -0.445>, 0.228
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.487, 6.39, 0.446>, 0.249
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.498, 6.378, 1.486>, 0.232
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.391, 6.438, 2.584>, 0.182
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.632, 6.387, 3.447>, 0.203
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-4.646, 6.46, 4.502>, 0.238
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.479, 0.551, -4.515>, 0.228
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.558, 0.508, -3.572>, 0.256
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.385, 0.535, -2.627>, 0.227
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.471, 0.616, -1.496>, 0.212
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.421, 0.625, -0.396>, 0.266
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.552, 0.566, 0.403>, 0.229
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.646, 0.636, 1.479>, 0.227
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.558, 0.617, 2.353>, 0.182
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.432, 0.638, 3.588>, 0.272
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.565, 0.508, 4.551>, 0.205
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.367, 1.195, -4.549>, 0.254
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.423, 1.35, -3.432>, 0.265
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.378, 1.234, -2.558>, 0.208
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.404, 1.218, -1.571>, 0.223
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.443, 1.327, -0.538>, 0.21
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.506, 1.345, 0.611>, 0.252
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.363, 1.258, 1.399>, 0.259
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.59, 1.169, 2.562>, 0.263
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.442, 1.25, 3.511>, 0.271
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.464, 1.338, 4.606>, 0.245
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.354, 1.963, -4.628>, 0.2
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.36, 1.985, -3.382>, 0.232
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.633, 1.907, -2.508>, 0.24
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.362, 1.901, -1.545>, 0.272
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.411, 1.969, -0.516>, 0.186
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.562, 1.949, 0.496>, 0.241
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.456, 1.9, 1.377>, 0.269
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.431, 1.823, 2.568>, 0.268
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.602, 1.919, 3.504>, 0.273
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.479, 1.997, 4.418>, 0.224
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.494, 2.513, -4.56>, 0.224
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.393, 2.567, -3.507>, 0.204
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.482, 2.474, -2.613>, 0.215
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.63, 2.585, -1.478>, 0.266
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.523, 2.503, -0.568>, 0.275
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.42, 2.465, 0.52>, 0.23
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.389, 2.454, 1.497>, 0.258
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.41, 2.561, 2.584>, 0.253
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.444, 2.503, 3.56>, 0.27
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.383, 2.456, 4.643>, 0.203
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.391, 3.122, -4.547>, 0.269
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.436, 3.192, -3.621>, 0.227
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.592, 3.125, -2.528>, 0.22
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.448, 3.236, -1.629>, 0.271
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.367, 3.254, -0.397>, 0.28
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.376, 3.22, 0.443>, 0.267
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.638, 3.241, 1.53>, 0.279
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.46, 3.171, 2.535>, 0.264
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.389, 3.259, 3.535>, 0.233
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.389, 3.118, 4.366>, 0.26
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.381, 3.885, -4.493>, 0.187
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.432, 3.825, -3.576>, 0.216
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.449, 3.881, -2.574>, 0.267
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.535, 3.822, -1.48>, 0.249
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.424, 3.825, -0.537>, 0.197
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.446, 3.946, 0.522>, 0.239
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.59, 3.786, 1.577>, 0.229
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.384, 3.883, 2.418>, 0.25
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.51, 3.76, 3.642>, 0.226
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.366, 3.794, 4.497>, 0.233
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.365, 4.452, -4.477>, 0.223
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.426, 4.599, -3.457>, 0.247
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.629, 4.526, -2.635>, 0.264
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.543, 4.543, -1.482>, 0.181
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.526, 4.519, -0.363>, 0.208
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.612, 4.437, 0.469>, 0.259
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.527, 4.504, 1.43>, 0.221
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.408, 4.529, 2.646>, 0.193
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.583, 4.41, 3.619>, 0.208
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.576, 4.475, 4.368>, 0.263
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.355, 5.186, -4.448>, 0.254
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.478, 5.072, -3.618>, 0.192
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.36, 5.058, -2.577>, 0.264
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.389, 5.218, -1.525>, 0.212
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.491, 5.177, -0.521>, 0.213
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.381, 5.119, 0.572>, 0.248
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.551, 5.088, 1.525>, 0.201
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.523, 5.142, 2.413>, 0.276
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.514, 5.103, 3.577>, 0.184
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.588, 5.141, 4.64>, 0.22
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.439, 5.771, -4.467>, 0.234
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.522, 5.81, -3.401>, 0.221
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.552, 5.869, -2.538>, 0.277
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.391, 5.746, -1.629>, 0.208
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.397, 5.805, -0.418>, 0.212
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.631, 5.711, 0.472>, 0.201
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.621, 5.816, 1.469>, 0.259
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.422, 5.858, 2.384>, 0.227
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.474, 5.845, 3.583>, 0.271
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.453, 5.838, 4.597>, 0.211
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.629, 6.476, -4.353>, 0.275
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.368, 6.403, -3.413>, 0.256
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.583, 6.379, -2.649>, 0.268
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.424, 6.397, -1.365>, 0.255
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.497, 6.493, -0.435>, 0.208
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.591, 6.364, 0.416>, 0.184
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.58, 6.518, 1.535>, 0.226
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.379, 6.435, 2.515>, 0.258
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.545, 6.488, 3.477>, 0.231
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-3.519, 6.413, 4.397>, 0.217
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.489, 0.585, -4.422>, 0.228
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.448, 0.556, -3.436>, 0.244
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.405, 0.582, -2.359>, 0.188
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.575, 0.664, -1.481>, 0.265
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.451, 0.606, -0.584>, 0.261
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.581, 0.525, 0.556>, 0.199
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.509, 0.662, 1.553>, 0.198
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.481, 0.655, 2.371>, 0.205
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.374, 0.565, 3.549>, 0.241
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.541, 0.611, 4.595>, 0.235
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.64, 1.21, -4.395>, 0.202
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.378, 1.196, -3.506>, 0.279
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.554, 1.301, -2.413>, 0.192
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.629, 1.259, -1.624>, 0.23
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.603, 1.347, -0.414>, 0.26
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.429, 1.211, 0.411>, 0.241
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.544, 1.161, 1.638>, 0.271
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.641, 1.193, 2.536>, 0.218
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.612, 1.25, 3.44>, 0.217
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.391, 1.233, 4.406>, 0.253
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.396, 1.924, -4.521>, 0.231
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.611, 1.821, -3.563>, 0.236
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.629, 1.845, -2.592>, 0.277
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.628, 1.964, -1.483>, 0.225
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.529, 1.976, -0.633>, 0.224
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.512, 1.883, 0.456>, 0.266
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.406, 1.806, 1.544>, 0.208
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.579, 1.988, 2.416>, 0.269
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.647, 1.92, 3.393>, 0.227
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.502, 1.961, 4.504>, 0.25
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.397, 2.471, -4.527>, 0.258
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.647, 2.478, -3.401>, 0.249
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.566, 2.471, -2.527>, 0.27
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.496, 2.582, -1.485>, 0.257
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.588, 2.459, -0.416>, 0.213
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.443, 2.505, 0.428>, 0.195
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.525, 2.632, 1.406>, 0.276
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.576, 2.496, 2.462>, 0.234
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.451, 2.469, 3.544>, 0.224
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.43, 2.548, 4.505>, 0.265
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.474, 3.297, -4.404>, 0.199
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.365, 3.238, -3.46>, 0.256
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.371, 3.113, -2.633>, 0.204
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.514, 3.132, -1.51>, 0.244
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.458, 3.219, -0.402>, 0.279
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.459, 3.161, 0.555>, 0.269
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.532, 3.194, 1.517>, 0.256
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.598, 3.206, 2.643>, 0.184
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.638, 3.125, 3.553>, 0.223
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.618, 3.124, 4.648>, 0.208
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.373, 3.874, -4.51>, 0.229
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.571, 3.768, -3.457>, 0.263
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.414, 3.946, -2.547>, 0.221
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.426, 3.9, -1.48>, 0.263
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.534, 3.901, -0.436>, 0.259
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.551, 3.908, 0.456>, 0.259
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.601, 3.851, 1.517>, 0.208
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.621, 3.851, 2.65>, 0.188
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.543, 3.871, 3.39>, 0.258
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.418, 3.88, 4.498>, 0.185
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.606, 4.505, -4.514>, 0.238
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.608, 4.517, -3.585>, 0.208
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.537, 4.446, -2.425>, 0.277
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.39, 4.547, -1.443>, 0.249
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.386, 4.434, -0.499>, 0.219
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.351, 4.444, 0.4>, 0.234
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.406, 4.592, 1.588>, 0.188
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.512, 4.591, 2.452>, 0.194
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.647, 4.516, 3.541>, 0.26
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.583, 4.495, 4.59>, 0.241
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.641, 5.193, -4.551>, 0.238
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.379, 5.15, -3.491>, 0.223
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.437, 5.24, -2.571>, 0.273
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.442, 5.065, -1.635>, 0.208
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.456, 5.224, -0.61>, 0.256
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.513, 5.144, 0.608>, 0.211
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.467, 5.077, 1.356>, 0.273
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.365, 5.104, 2.562>, 0.187
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.56, 5.126, 3.384>, 0.269
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.549, 5.176, 4.573>, 0.271
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.416, 5.78, -4.36>, 0.266
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.642, 5.756, -3.469>, 0.23
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.579, 5.807, -2.586>, 0.259
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.567, 5.826, -1.446>, 0.216
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.483, 5.854, -0.465>, 0.231
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.41, 5.886, 0.633>, 0.188
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.352, 5.861, 1.417>, 0.198
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.453, 5.818, 2.54>, 0.195
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.488, 5.845, 3.47>, 0.193
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.604, 5.74, 4.627>, 0.272
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.375, 6.378, -4.39>, 0.236
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.507, 6.51, -3.65>, 0.254
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.582, 6.466, -2.625>, 0.241
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.499, 6.412, -1.355>, 0.265
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.529, 6.444, -0.62>, 0.219
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.485, 6.425, 0.602>, 0.202
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.511, 6.508, 1.638>, 0.28
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.497, 6.419, 2.359>, 0.187
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.611, 6.376, 3.618>, 0.202
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-2.458, 6.508, 4.423>, 0.187
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.395, 0.602, -4.631>, 0.241
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.458, 0.529, -3.563>, 0.253
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.359, 0.54, -2.626>, 0.251
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.447, 0.594, -1.399>, 0.186
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.531, 0.662, -0.627>, 0.223
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.474, 0.656, 0.43>, 0.251
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.508, 0.65, 1.503>, 0.23
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.405, 0.653, 2.52>, 0.199
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.572, 0.504, 3.425>, 0.222
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.638, 0.689, 4.612>, 0.264
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.502, 1.312, -4.53>, 0.199
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.394, 1.196, -3.54>, 0.225
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.477, 1.162, -2.487>, 0.276
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.355, 1.312, -1.487>, 0.258
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.645, 1.226, -0.513>, 0.209
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.508, 1.344, 0.401>, 0.204
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.623, 1.191, 1.403>, 0.216
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.64, 1.259, 2.414>, 0.265
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.481, 1.231, 3.464>, 0.209
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.602, 1.186, 4.396>, 0.183
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.574, 1.804, -4.632>, 0.204
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.586, 1.928, -3.542>, 0.225
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.576, 1.859, -2.479>, 0.272
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.445, 1.929, -1.609>, 0.22
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.515, 1.808, -0.562>, 0.27
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.609, 1.944, 0.587>, 0.224
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.484, 1.825, 1.596>, 0.216
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.391, 1.88, 2.573>, 0.246
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.587, 1.904, 3.375>, 0.268
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.506, 1.999, 4.481>, 0.203
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.469, 2.648, -4.393>, 0.183
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.402, 2.626, -3.534>, 0.253
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.616, 2.596, -2.64>, 0.192
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.566, 2.562, -1.633>, 0.253
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.543, 2.54, -0.427>, 0.197
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.365, 2.549, 0.361>, 0.213
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.638, 2.595, 1.63>, 0.275
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.557, 2.614, 2.41>, 0.227
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.492, 2.451, 3.507>, 0.199
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.607, 2.644, 4.433>, 0.209
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.435, 3.133, -4.632>, 0.2
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.431, 3.127, -3.361>, 0.223
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.577, 3.287, -2.406>, 0.276
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.633, 3.112, -1.546>, 0.182
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.381, 3.291, -0.434>, 0.243
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.358, 3.281, 0.467>, 0.199
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.42, 3.116, 1.471>, 0.207
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.418, 3.276, 2.628>, 0.206
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.498, 3.127, 3.513>, 0.235
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.418, 3.276, 4.595>, 0.237
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.53, 3.937, -4.412>, 0.225
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.421, 3.806, -3.498>, 0.248
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.393, 3.923, -2.423>, 0.184
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.602, 3.926, -1.513>, 0.229
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.568, 3.789, -0.576>, 0.268
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.579, 3.912, 0.527>, 0.27
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.613, 3.9, 1.606>, 0.225
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.627, 3.783, 2.633>, 0.217
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.466, 3.908, 3.372>, 0.181
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.378, 3.766, 4.472>, 0.271
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.424, 4.424, -4.604>, 0.274
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.456, 4.501, -3.454>, 0.213
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.377, 4.45, -2.573>, 0.257
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.377, 4.425, -1.444>, 0.187
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.576, 4.567, -0.59>, 0.218
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.381, 4.475, 0.582>, 0.215
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.514, 4.442, 1.63>, 0.26
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.617, 4.553, 2.474>, 0.195
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.641, 4.405, 3.608>, 0.265
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.453, 4.545, 4.649>, 0.213
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.351, 5.223, -4.404>, 0.257
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.595, 5.233, -3.498>, 0.224
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.496, 5.157, -2.483>, 0.241
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.421, 5.152, -1.589>, 0.248
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.364, 5.223, -0.477>, 0.242
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.416, 5.089, 0.456>, 0.205
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.616, 5.094, 1.623>, 0.222
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.483, 5.079, 2.643>, 0.187
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.58, 5.221, 3.574>, 0.252
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.587, 5.226, 4.604>, 0.257
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.369, 5.71, -4.555>, 0.265
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.449, 5.783, -3.602>, 0.203
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.452, 5.822, -2.43>, 0.216
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.5, 5.808, -1.613>, 0.223
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.602, 5.77, -0.483>, 0.262
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.355, 5.76, 0.377>, 0.252
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.392, 5.848, 1.408>, 0.277
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.573, 5.759, 2.453>, 0.189
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.431, 5.749, 3.372>, 0.194
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.606, 5.834, 4.352>, 0.218
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.416, 6.472, -4.635>, 0.275
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.378, 6.507, -3.595>, 0.22
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.514, 6.36, -2.594>, 0.215
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.513, 6.379, -1.427>, 0.27
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.605, 6.492, -0.534>, 0.195
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.412, 6.42, 0.613>, 0.274
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.39, 6.392, 1.638>, 0.221
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.478, 6.361, 2.393>, 0.252
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.572, 6.52, 3.365>, 0.244
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-1.393, 6.385, 4.408>, 0.246
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.627, 0.585, -4.597>, 0.224
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.523, 0.673, -3.601>, 0.19
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.519, 0.523, -2.523>, 0.202
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.601, 0.516, -1.58>, 0.229
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.466, 0.541, -0.371>, 0.201
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.639, 0.639, 0.516>, 0.243
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.507, 0.535, 1.454>, 0.233
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.379, 0.538, 2.565>, 0.254
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.416, 0.652, 3.432>, 0.235
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.439, 0.652, 4.5>, 0.229
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.61, 1.157, -4.524>, 0.203
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.647, 1.23, -3.569>, 0.245
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.376, 1.281, -2.383>, 0.186
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.641, 1.254, -1.566>, 0.194
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.543, 1.321, -0.607>, 0.268
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.426, 1.343, 0.43>, 0.214
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.368, 1.247, 1.352>, 0.274
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.612, 1.273, 2.441>, 0.259
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.45, 1.189, 3.46>, 0.204
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.634, 1.285, 4.421>, 0.203
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.451, 1.92, -4.527>, 0.23
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.425, 1.899, -3.623>, 0.272
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.391, 1.991, -2.632>, 0.259
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.493, 1.841, -1.53>, 0.222
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.636, 1.841, -0.39>, 0.18
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.439, 1.952, 0.589>, 0.253
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.531, 1.842, 1.618>, 0.21
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.428, 1.888, 2.64>, 0.189
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.524, 1.881, 3.615>, 0.214
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.573, 1.837, 4.512>, 0.249
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.374, 2.508, -4.412>, 0.241
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.476, 2.531, -3.65>, 0.206
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.495, 2.534, -2.556>, 0.278
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.558, 2.592, -1.386>, 0.272
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.495, 2.586, -0.569>, 0.241
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.414, 2.628, 0.393>, 0.276
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.487, 2.579, 1.467>, 0.208
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.594, 2.458, 2.623>, 0.182
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.487, 2.637, 3.35>, 0.207
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.421, 2.538, 4.367>, 0.279
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.487, 3.214, -4.457>, 0.233
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.604, 3.132, -3.645>, 0.224
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.589, 3.208, -2.583>, 0.184
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.526, 3.138, -1.47>, 0.239
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.373, 3.116, -0.415>, 0.186
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.517, 3.113, 0.437>, 0.181
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.513, 3.154, 1.428>, 0.2
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.553, 3.227, 2.586>, 0.248
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.62, 3.13, 3.366>, 0.184
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.392, 3.137, 4.442>, 0.201
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.45, 3.884, -4.488>, 0.231
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.38, 3.939, -3.448>, 0.231
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.447, 3.841, -2.527>, 0.213
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.523, 3.929, -1.365>, 0.248
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.437, 3.926, -0.646>, 0.202
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.384, 3.891, 0.46>, 0.197
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.411, 3.818, 1.572>, 0.215
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.649, 3.799, 2.357>, 0.185
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.646, 3.871, 3.536>, 0.253
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.397, 3.779, 4.644>, 0.19
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.594, 4.49, -4.521>, 0.245
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.378, 4.534, -3.425>, 0.26
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.498, 4.473, -2.4>, 0.235
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.475, 4.558, -1.364>, 0.192
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.496, 4.52, -0.636>, 0.225
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.434, 4.403, 0.422>, 0.216
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.564, 4.58, 1.414>, 0.188
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.414, 4.584, 2.61>, 0.261
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.503, 4.493, 3.533>, 0.274
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.492, 4.591, 4.5>, 0.183
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.64, 5.245, -4.524>, 0.233
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.392, 5.176, -3.597>, 0.233
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.352, 5.225, -2.643>, 0.259
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.552, 5.242, -1.51>, 0.211
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.517, 5.248, -0.583>, 0.256
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.361, 5.141, 0.591>, 0.271
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.624, 5.242, 1.473>, 0.265
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.619, 5.237, 2.364>, 0.218
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.602, 5.065, 3.481>, 0.252
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.52, 5.221, 4.477>, 0.262
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.593, 5.88, -4.445>, 0.206
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.4, 5.878, -3.619>, 0.247
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.614, 5.842, -2.49>, 0.255
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.556, 5.758, -1.482>, 0.248
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.527, 5.847, -0.642>, 0.244
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.507, 5.883, 0.542>, 0.266
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.503, 5.836, 1.367>, 0.2
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.476, 5.798, 2.643>, 0.2
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.548, 5.714, 3.525>, 0.227
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.612, 5.817, 4.378>, 0.227
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.646, 6.403, -4.44>, 0.204
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.527, 6.527, -3.523>, 0.254
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.64, 6.476, -2.629>, 0.2
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.624, 6.534, -1.615>, 0.269
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.495, 6.442, -0.556>, 0.222
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.443, 6.351, 0.425>, 0.267
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.637, 6.367, 1.367>, 0.232
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.539, 6.497, 2.516>, 0.205
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.585, 6.48, 3.4>, 0.22
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <-0.548, 6.433, 4.619>, 0.254
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.507, 0.593, -4.638>, 0.254
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.468, 0.626, -3.394>, 0.247
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.356, 0.513, -2.591>, 0.233
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.569, 0.534, -1.581>, 0.234
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.575, 0.502, -0.614>, 0.228
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.443, 0.596, 0.614>, 0.201
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.377, 0.572, 1.533>, 0.198
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.613, 0.588, 2.448>, 0.269
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.427, 0.641, 3.444>, 0.224
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.381, 0.58, 4.57>, 0.245
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.383, 1.198, -4.525>, 0.217
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.451, 1.223, -3.477>, 0.248
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.474, 1.257, -2.519>, 0.238
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.489, 1.161, -1.506>, 0.203
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.456, 1.211, -0.515>, 0.246
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.65, 1.262, 0.395>, 0.258
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.58, 1.168, 1.383>, 0.186
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.469, 1.348, 2.467>, 0.275
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.388, 1.294, 3.477>, 0.258
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.605, 1.31, 4.351>, 0.268
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.624, 1.915, -4.355>, 0.226
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.649, 1.914, -3.52>, 0.252
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.475, 1.986, -2.406>, 0.256
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.497, 1.827, -1.586>, 0.236
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.569, 1.949, -0.577>, 0.242
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.374, 1.952, 0.385>, 0.206
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.502, 1.883, 1.445>, 0.214
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.397, 1.87, 2.608>, 0.253
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.573, 1.946, 3.546>, 0.24
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.547, 1.8, 4.564>, 0.212
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.567, 2.496, -4.545>, 0.189
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.563, 2.497, -3.41>, 0.214
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.489, 2.478, -2.456>, 0.274
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.43, 2.535, -1.615>, 0.205
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.642, 2.648, -0.496>, 0.227
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.535, 2.601, 0.41>, 0.224
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.47, 2.641, 1.536>, 0.274
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.518, 2.486, 2.449>, 0.249
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.417, 2.489, 3.483>, 0.257
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.487, 2.531, 4.61>, 0.182
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.597, 3.142, -4.647>, 0.215
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.601, 3.113, -3.377>, 0.189
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.567, 3.172, -2.565>, 0.196
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.634, 3.268, -1.447>, 0.221
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.622, 3.288, -0.644>, 0.224
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.622, 3.16, 0.578>, 0.279
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.463, 3.2, 1.399>, 0.214
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.423, 3.125, 2.583>, 0.251
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.441, 3.288, 3.623>, 0.255
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.575, 3.192, 4.591>, 0.279
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.555, 3.763, -4.583>, 0.244
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.356, 3.786, -3.463>, 0.202
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.625, 3.797, -2.52>, 0.259
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.428, 3.778, -1.425>, 0.217
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.533, 3.929, -0.368>, 0.207
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.433, 3.908, 0.376>, 0.191
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.384, 3.758, 1.535>, 0.222
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.417, 3.821, 2.541>, 0.263
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.449, 3.944, 3.622>, 0.254
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.504, 3.933, 4.592>, 0.26
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.539, 4.511, -4.576>, 0.263
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.393, 4.49, -3.518>, 0.211
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.555, 4.469, -2.587>, 0.194
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.562, 4.479, -1.399>, 0.196
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.535, 4.588, -0.434>, 0.278
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.632, 4.435, 0.47>, 0.187
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.496, 4.449, 1.441>, 0.192
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.615, 4.445, 2.504>, 0.245
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.483, 4.416, 3.378>, 0.188
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.398, 4.413, 4.374>, 0.235
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.397, 5.145, -4.399>, 0.19
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.594, 5.093, -3.475>, 0.247
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.393, 5.09, -2.562>, 0.22
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.632, 5.207, -1.462>, 0.237
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.512, 5.145, -0.592>, 0.239
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.568, 5.222, 0.539>, 0.226
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.371, 5.122, 1.441>, 0.192
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.548, 5.223, 2.627>, 0.236
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.475, 5.126, 3.579>, 0.26
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.594, 5.24, 4.484>, 0.211
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.639, 5.82, -4.556>, 0.215
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.445, 5.703, -3.376>, 0.215
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.625, 5.87, -2.636>, 0.277
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.52, 5.778, -1.439>, 0.189
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.393, 5.799, -0.504>, 0.219
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.51, 5.745, 0.507>, 0.19
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.586, 5.826, 1.452>, 0.254
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.452, 5.839, 2.353>, 0.237
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.367, 5.826, 3.419>, 0.233
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.534, 5.759, 4.442>, 0.25
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.625, 6.464, -4.364>, 0.203
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.363, 6.393, -3.56>, 0.242
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.481, 6.482, -2.377>, 0.258
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.559, 6.357, -1.384>, 0.248
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.53, 6.532, -0.624>, 0.265
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.562, 6.498, 0.598>, 0.235
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.646, 6.486, 1.386>, 0.181
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.361, 6.418, 2.488>, 0.244
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.472, 6.377, 3.586>, 0.227
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <0.5, 6.524, 4.568>, 0.186
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.483, 0.68, -4.549>, 0.246
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.568, 0.562, -3.521>, 0.256
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.384, 0.675, -2.613>, 0.193
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.611, 0.601, -1.415>, 0.18
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.416, 0.538, -0.555>, 0.274
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.553, 0.654, 0.526>, 0.268
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.628, 0.681, 1.465>, 0.19
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.511, 0.669, 2.52>, 0.279
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.629, 0.506, 3.364>, 0.256
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.547, 0.54, 4.61>, 0.228
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.65, 1.179, -4.61>, 0.215
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.371, 1.301, -3.643>, 0.246
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.358, 1.218, -2.515>, 0.241
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.429, 1.162, -1.546>, 0.24
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.534, 1.268, -0.455>, 0.2
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.52, 1.298, 0.356>, 0.185
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.367, 1.185, 1.409>, 0.194
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.594, 1.244, 2.635>, 0.274
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.424, 1.249, 3.645>, 0.191
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.638, 1.341, 4.591>, 0.204
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.405, 1.998, -4.552>, 0.246
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.426, 1.825, -3.421>, 0.246
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.413, 1.946, -2.423>, 0.225
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.582, 1.92, -1.519>, 0.264
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.603, 1.868, -0.411>, 0.212
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.384, 1.925, 0.596>, 0.272
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.353, 1.829, 1.526>, 0.244
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.518, 1.872, 2.594>, 0.27
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.536, 1.816, 3.545>, 0.235
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.43, 1.801, 4.376>, 0.221
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.594, 2.55, -4.398>, 0.227
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.53, 2.557, -3.36>, 0.198
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.473, 2.637, -2.616>, 0.276
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.568, 2.606, -1.629>, 0.256
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.452, 2.617, -0.637>, 0.264
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.505, 2.63, 0.635>, 0.271
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.552, 2.455, 1.644>, 0.207
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.503, 2.548, 2.537>, 0.195
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.515, 2.562, 3.602>, 0.239
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.455, 2.526, 4.561>, 0.258
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.446, 3.259, -4.392>, 0.219
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.58, 3.216, -3.421>, 0.277
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.439, 3.294, -2.389>, 0.254
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.36, 3.246, -1.455>, 0.243
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.474, 3.203, -0.52>, 0.188
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.64, 3.152, 0.449>, 0.276
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.422, 3.17, 1.459>, 0.251
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.492, 3.137, 2.508>, 0.2
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.41, 3.257, 3.404>, 0.216
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.602, 3.161, 4.544>, 0.201
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.612, 3.879, -4.579>, 0.189
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.427, 3.849, -3.429>, 0.264
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.354, 3.767, -2.642>, 0.273
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.472, 3.873, -1.466>, 0.251
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.416, 3.841, -0.433>, 0.22
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.433, 3.905, 0.55>, 0.236
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.362, 3.845, 1.434>, 0.202
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.522, 3.927, 2.439>, 0.238
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.633, 3.823, 3.436>, 0.211
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.386, 3.854, 4.471>, 0.238
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.478, 4.577, -4.397>, 0.256
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.359, 4.534, -3.595>, 0.251
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.633, 4.478, -2.366>, 0.229
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.595, 4.44, -1.405>, 0.247
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.592, 4.407, -0.509>, 0.263
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.396, 4.413, 0.482>, 0.182
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.608, 4.557, 1.364>, 0.227
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.499, 4.575, 2.515>, 0.181
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.625, 4.505, 3.494>, 0.278
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.365, 4.508, 4.546>, 0.18
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.514, 5.062, -4.364>, 0.249
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.535, 5.191, -3.505>, 0.227
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.495, 5.193, -2.374>, 0.244
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.424, 5.082, -1.431>, 0.27
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.482, 5.076, -0.442>, 0.245
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.644, 5.228, 0.572>, 0.223
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.528, 5.095, 1.649>, 0.241
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.475, 5.053, 2.466>, 0.181
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.433, 5.129, 3.392>, 0.223
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.373, 5.097, 4.452>, 0.28
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.517, 5.76, -4.417>, 0.24
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.415, 5.802, -3.599>, 0.241
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.558, 5.893, -2.377>, 0.271
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.437, 5.893, -1.413>, 0.197
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.459, 5.892, -0.54>, 0.205
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.449, 5.819, 0.474>, 0.279
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.626, 5.883, 1.621>, 0.222
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.518, 5.728, 2.624>, 0.241
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.355, 5.873, 3.448>, 0.18
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.424, 5.882, 4.397>, 0.212
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.593, 6.355, -4.597>, 0.191
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.58, 6.415, -3.43>, 0.241
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.626, 6.363, -2.578>, 0.223
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.38, 6.354, -1.435>, 0.212
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.448, 6.465, -0.447>, 0.25
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.576, 6.545, 0.372>, 0.274
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.551, 6.39, 1.593>, 0.267
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.61, 6.394, 2.408>, 0.276
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.386, 6.367, 3.527>, 0.189
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <1.624, 6.48, 4.472>, 0.247
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.564, 0.642, -4.508>, 0.193
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.515, 0.626, -3.47>, 0.272
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.548, 0.647, -2.575>, 0.267
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.468, 0.63, -1.502>, 0.185
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.446, 0.69, -0.64>, 0.25
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.623, 0.636, 0.493>, 0.212
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.588, 0.523, 1.483>, 0.185
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.493, 0.601, 2.411>, 0.247
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.538, 0.635, 3.642>, 0.242
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.464, 0.686, 4.621>, 0.202
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.505, 1.269, -4.618>, 0.212
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.383, 1.273, -3.363>, 0.262
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.412, 1.265, -2.406>, 0.182
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.639, 1.317, -1.543>, 0.236
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.577, 1.266, -0.589>, 0.206
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.574, 1.172, 0.533>, 0.211
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.637, 1.196, 1.456>, 0.256
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.407, 1.161, 2.412>, 0.235
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.509, 1.303, 3.573>, 0.188
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.472, 1.261, 4.498>, 0.212
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.506, 1.923, -4.561>, 0.209
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.507, 1.982, -3.554>, 0.248
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.607, 1.834, -2.585>, 0.242
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.642, 1.938, -1.536>, 0.25
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.457, 1.863, -0.456>, 0.246
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.565, 1.936, 0.562>, 0.246
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.626, 1.8, 1.517>, 0.237
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.486, 1.922, 2.489>, 0.202
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.405, 2, 3.638>, 0.251
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.382, 1.814, 4.532>, 0.268
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.563, 2.582, -4.464>, 0.251
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.412, 2.538, -3.411>, 0.226
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.474, 2.603, -2.615>, 0.246
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.563, 2.541, -1.562>, 0.192
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.482, 2.638, -0.543>, 0.189
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.366, 2.5, 0.609>, 0.229
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.561, 2.491, 1.5>, 0.224
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.426, 2.633, 2.438>, 0.241
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.61, 2.468, 3.643>, 0.22
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.397, 2.63, 4.535>, 0.251
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.37, 3.132, -4.45>, 0.271
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.623, 3.239, -3.396>, 0.242
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.615, 3.198, -2.571>, 0.24
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.448, 3.228, -1.42>, 0.256
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.537, 3.28, -0.395>, 0.233
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.596, 3.217, 0.521>, 0.243
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.634, 3.223, 1.406>, 0.258
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.473, 3.154, 2.543>, 0.235
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.469, 3.256, 3.598>, 0.206
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.572, 3.231, 4.411>, 0.197
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.535, 3.797, -4.57>, 0.267
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.569, 3.909, -3.454>, 0.238
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.38, 3.762, -2.62>, 0.272
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.479, 3.861, -1.527>, 0.193
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.598, 3.796, -0.419>, 0.28
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.619, 3.872, 0.47>, 0.243
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.489, 3.779, 1.605>, 0.237
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.357, 3.814, 2.522>, 0.266
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.441, 3.774, 3.514>, 0.26
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.629, 3.802, 4.426>, 0.219
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.517, 4.529, -4.541>, 0.213
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.477, 4.544, -3.391>, 0.248
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.378, 4.551, -2.584>, 0.273
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.495, 4.518, -1.407>, 0.221
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.569, 4.569, -0.448>, 0.199
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.475, 4.563, 0.421>, 0.26
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.412, 4.439, 1.631>, 0.252
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.566, 4.444, 2.639>, 0.213
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.488, 4.476, 3.427>, 0.254
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.514, 4.403, 4.404>, 0.238
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.535, 5.18, -4.484>, 0.243
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.555, 5.116, -3.593>, 0.25
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.549, 5.082, -2.564>, 0.264
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.421, 5.051, -1.597>, 0.221
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.379, 5.1, -0.598>, 0.199
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.373, 5.232, 0.436>, 0.236
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.359, 5.056, 1.441>, 0.186
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.512, 5.231, 2.388>, 0.224
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.544, 5.195, 3.565>, 0.232
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.649, 5.133, 4.395>, 0.255
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.435, 5.717, -4.36>, 0.224
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.473, 5.821, -3.366>, 0.256
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.58, 5.877, -2.605>, 0.201
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.619, 5.719, -1.573>, 0.247
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.448, 5.821, -0.614>, 0.199
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.406, 5.785, 0.518>, 0.255
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.522, 5.847, 1.597>, 0.241
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.469, 5.78, 2.364>, 0.255
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.379, 5.796, 3.409>, 0.278
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.42, 5.823, 4.593>, 0.18
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.378, 6.441, -4.407>, 0.204
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.377, 6.538, -3.594>, 0.184
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.625, 6.499, -2.565>, 0.279
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.361, 6.492, -1.538>, 0.232
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.491, 6.423, -0.586>, 0.19
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.594, 6.385, 0.59>, 0.243
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.39, 6.517, 1.373>, 0.191
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.463, 6.442, 2.525>, 0.252
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.403, 6.499, 3.531>, 0.209
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <2.535, 6.494, 4.371>, 0.228
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.639, 0.577, -4.555>, 0.27
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.605, 0.557, -3.357>, 0.242
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.582, 0.548, -2.532>, 0.248
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.413, 0.682, -1.356>, 0.248
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.502, 0.626, -0.476>, 0.269
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.496, 0.503, 0.616>, 0.239
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.352, 0.697, 1.5>, 0.239
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.624, 0.516, 2.484>, 0.272
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.644, 0.657, 3.535>, 0.231
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.421, 0.58, 4.588>, 0.204
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.455, 1.28, -4.584>, 0.236
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.536, 1.269, -3.62>, 0.266
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.533, 1.191, -2.593>, 0.239
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.537, 1.175, -1.478>, 0.27
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.401, 1.252, -0.498>, 0.257
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.641, 1.336, 0.638>, 0.216
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.441, 1.207, 1.627>, 0.231
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.409, 1.225, 2.643>, 0.224
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.629, 1.191, 3.487>, 0.26
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.527, 1.212, 4.485>, 0.243
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.604, 1.945, -4.575>, 0.233
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.404, 1.963, -3.566>, 0.25
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.597, 1.859, -2.614>, 0.182
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.487, 1.945, -1.416>, 0.243
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.419, 1.985, -0.545>, 0.188
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.601, 1.965, 0.357>, 0.217
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.409, 1.933, 1.364>, 0.269
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.405, 1.899, 2.376>, 0.257
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.395, 1.992, 3.381>, 0.223
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.557, 1.833, 4.465>, 0.261
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.61, 2.604, -4.569>, 0.265
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.556, 2.525, -3.503>, 0.266
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.429, 2.599, -2.584>, 0.251
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.521, 2.624, -1.504>, 0.252
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.465, 2.505, -0.556>, 0.203
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.521, 2.461, 0.365>, 0.182
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.534, 2.515, 1.437>, 0.185
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.459, 2.565, 2.439>, 0.248
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.525, 2.495, 3.603>, 0.272
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.606, 2.583, 4.56>, 0.27
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.465, 3.103, -4.611>, 0.235
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.545, 3.176, -3.538>, 0.252
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.458, 3.294, -2.506>, 0.192
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.366, 3.197, -1.388>, 0.227
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.458, 3.203, -0.534>, 0.248
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.367, 3.145, 0.611>, 0.226
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.644, 3.268, 1.539>, 0.203
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.646, 3.206, 2.621>, 0.187
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.547, 3.275, 3.5>, 0.193
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.455, 3.107, 4.505>, 0.279
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.609, 3.797, -4.426>, 0.259
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.407, 3.911, -3.437>, 0.216
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.38, 3.912, -2.543>, 0.184
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.527, 3.942, -1.411>, 0.221
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.441, 3.902, -0.555>, 0.185
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.544, 3.851, 0.619>, 0.196
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.354, 3.792, 1.444>, 0.266
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.439, 3.826, 2.504>, 0.21
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.514, 3.931, 3.48>, 0.203
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.587, 3.837, 4.642>, 0.235
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.431, 4.52, -4.395>, 0.248
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.461, 4.487, -3.478>, 0.189
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.627, 4.49, -2.376>, 0.194
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.372, 4.448, -1.508>, 0.217
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.531, 4.534, -0.531>, 0.229
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.63, 4.487, 0.566>, 0.237
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.455, 4.517, 1.368>, 0.271
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.514, 4.486, 2.637>, 0.266
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.597, 4.493, 3.438>, 0.23
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.573, 4.494, 4.409>, 0.193
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.365, 5.24, -4.621>, 0.206
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.396, 5.111, -3.4>, 0.277
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.586, 5.134, -2.393>, 0.242
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.55, 5.14, -1.459>, 0.211
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.505, 5.18, -0.626>, 0.205
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.373, 5.097, 0.416>, 0.211
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.376, 5.207, 1.47>, 0.277
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.505, 5.073, 2.367>, 0.194
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.419, 5.161, 3.568>, 0.207
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.552, 5.08, 4.531>, 0.253
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.552, 5.825, -4.491>, 0.222
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.448, 5.715, -3.371>, 0.244
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.633, 5.759, -2.385>, 0.276
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.498, 5.84, -1.387>, 0.279
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.369, 5.728, -0.382>, 0.228
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.607, 5.878, 0.472>, 0.192
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.352, 5.858, 1.427>, 0.249
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.388, 5.758, 2.486>, 0.256
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.381, 5.799, 3.588>, 0.2
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.393, 5.876, 4.615>, 0.206
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.621, 6.397, -4.367>, 0.184
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.528, 6.545, -3.598>, 0.276
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.448, 6.376, -2.631>, 0.278
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.528, 6.378, -1.411>, 0.255
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.424, 6.512, -0.458>, 0.245
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.453, 6.391, 0.526>, 0.259
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.545, 6.441, 1.579>, 0.224
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.605, 6.472, 2.406>, 0.229
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.61, 6.493, 3.619>, 0.231
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <3.424, 6.385, 4.377>, 0.196
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.627, 0.648, -4.445>, 0.229
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.417, 0.633, -3.63>, 0.19
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.558, 0.608, -2.49>, 0.181
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.648, 0.501, -1.583>, 0.265
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.354, 0.641, -0.551>, 0.273
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.577, 0.677, 0.512>, 0.229
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.45, 0.679, 1.386>, 0.272
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.56, 0.608, 2.599>, 0.192
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.585, 0.543, 3.475>, 0.265
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.405, 0.653, 4.561>, 0.249
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.472, 1.171, -4.366>, 0.241
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.63, 1.348, -3.458>, 0.227
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.409, 1.312, -2.464>, 0.248
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.602, 1.255, -1.524>, 0.229
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.438, 1.282, -0.481>, 0.19
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.459, 1.289, 0.414>, 0.186
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.37, 1.209, 1.578>, 0.248
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.469, 1.318, 2.383>, 0.194
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.589, 1.341, 3.44>, 0.259
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.647, 1.307, 4.447>, 0.211
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.511, 1.867, -4.554>, 0.198
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.403, 1.992, -3.362>, 0.257
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.374, 1.961, -2.488>, 0.265
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.488, 1.822, -1.532>, 0.224
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.507, 1.92, -0.601>, 0.23
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.531, 1.941, 0.573>, 0.256
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.446, 1.868, 1.552>, 0.22
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.58, 1.872, 2.419>, 0.224
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.554, 1.896, 3.637>, 0.252
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.534, 1.997, 4.611>, 0.226
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.412, 2.453, -4.367>, 0.192
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.438, 2.463, -3.364>, 0.201
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.428, 2.464, -2.587>, 0.182
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.549, 2.538, -1.615>, 0.181
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.466, 2.481, -0.505>, 0.198
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.531, 2.595, 0.529>, 0.197
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.44, 2.471, 1.587>, 0.194
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.502, 2.481, 2.443>, 0.255
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.64, 2.506, 3.504>, 0.182
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.404, 2.557, 4.479>, 0.183
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.369, 3.181, -4.447>, 0.251
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.647, 3.192, -3.468>, 0.19
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.504, 3.108, -2.367>, 0.213
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.638, 3.179, -1.58>, 0.233
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.649, 3.159, -0.445>, 0.233
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.542, 3.26, 0.612>, 0.206
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.496, 3.21, 1.564>, 0.271
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.466, 3.12, 2.61>, 0.236
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.461, 3.237, 3.358>, 0.205
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.374, 3.22, 4.596>, 0.236
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.566, 3.851, -4.518>, 0.258
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.591, 3.773, -3.36>, 0.226
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.454, 3.807, -2.536>, 0.261
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.403, 3.831, -1.539>, 0.271
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.6, 3.772, -0.574>, 0.199
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.521, 3.851, 0.458>, 0.225
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.369, 3.778, 1.453>, 0.263
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.441, 3.846, 2.468>, 0.25
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.461, 3.858, 3.439>, 0.209
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.474, 3.812, 4.446>, 0.183
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.579, 4.559, -4.381>, 0.265
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.623, 4.418, -3.365>, 0.186
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.361, 4.59, -2.386>, 0.202
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.642, 4.527, -1.461>, 0.275
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.389, 4.57, -0.517>, 0.239
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.378, 4.53, 0.603>, 0.186
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.642, 4.527, 1.568>, 0.22
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.439, 4.568, 2.493>, 0.246
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.547, 4.509, 3.59>, 0.252
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.549, 4.471, 4.386>, 0.253
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.545, 5.205, -4.536>, 0.258
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.578, 5.147, -3.592>, 0.222
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.484, 5.138, -2.47>, 0.247
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.644, 5.241, -1.598>, 0.273
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.612, 5.062, -0.645>, 0.188
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.361, 5.219, 0.508>, 0.272
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.452, 5.086, 1.595>, 0.256
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.599, 5.192, 2.547>, 0.278
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.599, 5.117, 3.373>, 0.235
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.402, 5.223, 4.641>, 0.258
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.496, 5.858, -4.542>, 0.273
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.641, 5.756, -3.449>, 0.271
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.399, 5.841, -2.416>, 0.247
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.604, 5.753, -1.475>, 0.206
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.589, 5.773, -0.569>, 0.189
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.386, 5.8, 0.469>, 0.183
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.572, 5.809, 1.478>, 0.242
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.629, 5.805, 2.373>, 0.206
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.635, 5.858, 3.547>, 0.188
  pigment { rgb <0.15, 0.3, 0.85> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.402, 5.779, 4.499>, 0.256
  pigment { rgb <0.9, 0.5, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.438, 6.41, -4.434>, 0.257
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.533, 6.353, -3.501>, 0.217
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.374, 6.504, -2.488>, 0.191
  pigment { rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.599, 6.476, -1.573>, 0.203
  pigment { rgb <0.9, 0.8, 0.2> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.526, 6.467, -0.399>, 0.242
  pigment { rgb <0.1, 0.6, 0.6> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.351, 6.364, 0.516>, 0.186
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.398, 6.392, 1.443>, 0.212
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.625, 6.468, 2.525>, 0.235
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.608, 6.495, 3.417>, 0.188
  pigment { rgb <0.85, 0.15, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

sphere { <4.567, 6.463, 4.604>, 0.183
  pigment { rgb <0.55, 0.25, 0.8> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 40 reflection 0 }
  
}

