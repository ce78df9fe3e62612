// Image textures: where a hit lies on its object's texture (each shape file has its mapping;
// docs/scene-format.md, "Texture mapping"), and the image's colour there, decoded from sRGB per
// texel and then filtered. Twin of host/cpu/texture.cpp.
#ifndef LANCER_TEXTURE_GLSL
#define LANCER_TEXTURE_GLSL

// Texture coordinates (u, v) of a hit at point p, by its shape's mapping.
#define LANCER_TEXTURE_UV_CASE(NAME, name, Type, type, traits) \
    case SHAPE_##NAME:                                              \
        if (SCENE_HAS_##NAME) return name##_texture_uv(prim, hit, p); \
        break;
vec2 texture_uv(Hit hit, vec3 p) {
    Primitive prim = primitive_at(hit.primitive);
    if (OBJECT_SPACE_SHAPES) {  // a shape kept in its object's coordinates is mapped there
        ObjectFrame f = object_frame_at(prim.object);
        if (f.in_object_space != 0u) {
            p = object_point(f, p);
            hit.normal = unit_vector(object_gradient(f, hit.normal));
        }
    }
    switch (prim.type) {
        LANCER_SHAPES(LANCER_TEXTURE_UV_CASE)
    }
    return hit.uv;
}

vec3 texel_linear(TextureInfo t, int x, int y) {
    vec3 e = unpackUnorm4x8(texel_at(t.texel_offset + uint(y) * t.width + uint(x))).rgb;
    return mix(e / 12.92, pow((e + 0.055) / 1.055, vec3(2.4)), greaterThan(e, vec3(0.04045)));
}

// A texel index in [-size, 2 size) wrapped around, or held at the edge.
int texel_index(int i, int size, bool clamped) {
    if (clamped) return clamp(i, 0, size - 1);
    return i < 0 ? i + size : (i >= size ? i - size : i);
}

vec3 texture_color(uint index, vec2 uv) {
    TextureInfo t = texture_at(index);
    bool clamp_u = (t.flags & TEXTURE_CLAMP_U) != 0u;
    bool clamp_v = (t.flags & TEXTURE_CLAMP_V) != 0u;
    vec2 st = vec2(dot(t.to_image_s.xy, uv) + t.to_image_s.z, dot(t.to_image_t.xy, uv) + t.to_image_t.z);
    st = vec2(clamp_u ? clamp(st.x, 0.0, 1.0) : fract(st.x), clamp_v ? clamp(st.y, 0.0, 1.0) : fract(st.y));
    ivec2 size = ivec2(t.width, t.height);
    // Texel (i, j) covers [i, i + 1] x [j, j + 1] here; row 0 is the top of the image (t = 1).
    vec2 xy = vec2(st.x, 1.0 - st.y) * vec2(size);
    if ((t.flags & TEXTURE_NEAREST) != 0u) {
        ivec2 i = ivec2(floor(xy));
        return texel_linear(t, texel_index(i.x, size.x, clamp_u), texel_index(i.y, size.y, clamp_v));
    }
    xy -= 0.5;  // bilinear between the four texels whose centres surround xy
    vec2 base = floor(xy);
    vec2 f = xy - base;
    ivec2 i0 = ivec2(base);
    int xa = texel_index(i0.x, size.x, clamp_u), xb = texel_index(i0.x + 1, size.x, clamp_u);
    int ya = texel_index(i0.y, size.y, clamp_v), yb = texel_index(i0.y + 1, size.y, clamp_v);
    vec3 top = mix(texel_linear(t, xa, ya), texel_linear(t, xb, ya), f.x);
    vec3 bottom = mix(texel_linear(t, xa, yb), texel_linear(t, xb, yb), f.x);
    return mix(top, bottom, f.y);
}

#endif
