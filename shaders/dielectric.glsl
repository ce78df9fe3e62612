// Transparent materials: the media a ray is inside, Fresnel's equations, refraction, Beer-Lambert
// absorption, and shadow rays through transparent objects. Twin of host/cpu/dielectric.cpp;
// docs/scene-format.md ("Refraction") states the model.
#ifndef LANCER_DIELECTRIC_GLSL
#define LANCER_DIELECTRIC_GLSL

// Below this remaining weight a ray cannot change the 8-bit result (< 1/4 of a level).
const float MIN_WEIGHT = 1.0 / 1024.0;

float max3(vec3 v) { return max(v.r, max(v.g, v.b)); }

bool is_transparent(Material m) { return max3(m.transmission.rgb) > 0.0; }

// A shape without an inside (SHAPE_SHEET: rectangles) is a thin sheet, which reflects and
// transmits but neither bends the ray nor changes the medium.
bool is_thin_sheet(uint primitive) { return (shape_traits(primitive_at(primitive).type) & SHAPE_SHEET) != 0u; }

const uint MEDIA_DEPTH = 4u;
const uint NO_MEDIUM = 0xffffffffu;  // air: ior 1, no absorption

// The transparent materials a ray is inside, outermost first, innermost at count - 1.
struct Media {
    uvec4 material;
    uint count;
};

Media no_media() { return Media(uvec4(NO_MEDIUM), 0u); }

uint innermost(Media media) { return media.count == 0u ? NO_MEDIUM : media.material[media.count - 1u]; }

// Crossing a surface of transparent material `mat` toggles being inside it: the innermost entry
// of `mat` is removed if there is one, else `mat` becomes the innermost medium. When all
// MEDIA_DEPTH entries are taken, the outermost is forgotten.
Media cross_surface(Media media, uint mat) {
    int found = -1;
    [[unroll]] for (int i = 0; i < int(MEDIA_DEPTH); ++i) {
        if (uint(i) < media.count && media.material[i] == mat) found = i;
    }
    if (found >= 0 || media.count == MEDIA_DEPTH) {
        int from = max(found, 0);  // close the gap at `found`, or drop the outermost entry
        [[unroll]] for (int i = 0; i < int(MEDIA_DEPTH) - 1; ++i) {
            if (i >= from) media.material[i] = media.material[i + 1];
        }
        media.material[MEDIA_DEPTH - 1u] = NO_MEDIUM;
        media.count -= 1u;
    }
    if (found < 0) {
        media.material[media.count] = mat;
        media.count += 1u;
    }
    return media;
}

float medium_ior(uint medium) { return medium == NO_MEDIUM ? 1.0 : material_at(medium).transmission.w; }

// Beer-Lambert: the fraction of light left after `distance` in the medium (0 at infinity).
vec3 absorption_over(uint medium, float distance) {
    if (medium == NO_MEDIUM) return vec3(1.0);
    vec3 a = material_at(medium).absorption.rgb;
    vec3 left = exp(-a * distance);
    return mix(left, vec3(1.0), equal(a, vec3(0.0)));  // a = 0: nothing absorbed, even at infinity
}

// Unpolarised Fresnel reflectance at an interface from index n1 (the ray's side) to n2, with
// cos_i the cosine of the angle of incidence; 1 beyond the critical angle (total internal
// reflection). cos_t is the cosine of the angle of refraction.
float fresnel(float cos_i, float n1, float n2, out float cos_t) {
    float eta = n1 / n2;
    float sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    cos_t = 0.0;
    if (sin2_t >= 1.0) return 1.0;
    cos_t = sqrt(1.0 - sin2_t);
    float rs = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
    float rp = (n2 * cos_i - n1 * cos_t) / (n2 * cos_i + n1 * cos_t);
    return 0.5 * (rs * rs + rp * rp);
}

// Snell's law: d refracted at a surface with unit normal n facing the incoming ray.
vec3 refraction(vec3 d, vec3 n, float eta, float cos_i, float cos_t) {
    return normalize(eta * d + (eta * cos_i - cos_t) * n);
}

// A refracted direction t kept across the surface of geometric normal n (facing the incoming ray):
// refraction about a shading normal (a smooth mesh's, a bump's) can bend a grazing ray back out;
// such a t is mirrored in the surface's plane, which leaves every t that crosses it unchanged and
// turns continuously (bounce_direction's rule for mirror rays). Twin of host/cpu/dielectric.cpp's.
vec3 crossing_direction(vec3 t, vec3 n) {
    float above = dot(t, n);
    return above > 0.0 ? t - 2.0 * above * n : t;
}

const uint MAX_SHADOW_CROSSINGS = 16u;

// The primitive that last blocked a shadow ray to each of the first 4 lights, tested first by
// the next shadow ray to that light (scene.glsl's SHADOW_HINTS): the samples of a pixel and their
// bounces mostly meet the same blocker. Which primitive is found first does not change whether
// the light is blocked, so the picture is the same.
uvec4 shadow_blockers = uvec4(NO_PRIMITIVE);
// And the element of a mesh or sphere set that did (shapes/element_tree.glsl's element hints).
uvec4 shadow_element_blockers = uvec4(NO_PRIMITIVE);

// The fraction of a light's colour that reaches the surface point `from` from the light point q,
// along a straight shadow ray that starts at `origin` (just off the surface) inside `media`: 0
// if an opaque surface is in the way; each transparent surface that changes the innermost
// medium (and each thin sheet) multiplies it by (1 - k_r) * T of its material, and media absorb
// along the way. No refraction and no Fresnel (no caustics; with photon mapping, transparent
// surfaces block shadow rays and the caustic photons bring that light). More than MAX_SHADOW_CROSSINGS
// surfaces block the light. Distances are measured between surface points, not from the offset
// origins, so absorption sees the true thickness. `light`: the light's index (shadow_blockers).
vec3 transmittance(vec3 from, vec3 origin, vec3 q, Media media, uint light) {
    vec3 through = vec3(1.0);
    for (uint k = 0u; k <= MAX_SHADOW_CROSSINGS; ++k) {
        vec3 to_light = q - origin;
        float dist = length(to_light);
        Ray ray = Ray(origin, to_light / dist);
        Nearest best;
        uint medium = innermost(media);
        // Without transparent materials any hit blocks the light, so the first one found will do;
        // so it does with photon mapping, where the light through glass arrives as photons.
        // (One call of trace_scene for both cases: each call site inlines the whole intersection
        // code, which lavapipe then compiles, even where it is dead.)
        const bool any_hit_blocks = !SCENE_HAS_TRANSPARENCY || SCENE_HAS_PHOTONS;
        bool hinted = SHADOW_HINTS && any_hit_blocks && light < 4u;
        bool element_hinted = ELEMENT_HINTS && any_hit_blocks && light < 4u;
        if (ELEMENT_HINTS) {
            element_hint = element_hinted ? shadow_element_blockers[light] : NO_PRIMITIVE;
            element_blocker = NO_PRIMITIVE;
        }
        // The light's direction grid (point and spot lights: q is the light's position).
        uint grid = any_hit_blocks && DIRECTION_GRID_LIGHT + light < DIRECTION_GRID_COUNT ? DIRECTION_GRID_LIGHT + light : NO_GRID;
        if (!trace_scene(ray, 0.0, dist, any_hit_blocks, hinted ? shadow_blockers[light] : NO_PRIMITIVE, grid, best)) {
            return any_hit_blocks ? through : through * absorption_over(medium, length(q - from));
        }
        if (hinted) shadow_blockers[light] = best.prim;
        if (element_hinted) shadow_element_blockers[light] = element_blocker;
        if (any_hit_blocks || k == MAX_SHADOW_CROSSINGS) break;
        // A CSG hit filters the light by its leaf's material (uv.x: the leaf's primitive). It goes on
        // along its own line: the leaf's normal would need the leaf intersected again, a second
        // copy of every solid's code here (csg.toml 9% slower).
        bool csg = SCENE_HAS_CSG && primitive_at(best.prim).type == SHAPE_CSG;
        uint mat = csg ? primitive_at(uint(best.uv.x)).material : hit_material(best.prim, best.uv);
        Material m = material_at(mat);
        if (!is_transparent(m)) break;
        vec3 p = ray.origin + best.t * ray.dir;
        through *= absorption_over(medium, length(p - from));
        Media beyond = is_thin_sheet(best.prim) ? media : cross_surface(media, mat);
        if (is_thin_sheet(best.prim) || innermost(beyond) != medium) through *= (1.0 - m.reflection) * m.transmission.rgb;
        if (max3(through) < MIN_WEIGHT) break;
        media = beyond;
        from = p;
        float error = best.error;
        vec3 n = csg ? -ray.dir : primitive_normal(best.prim, ray, best.t, p, best.uv, error);
        origin = through_surface(best.prim, p, n, ray.dir, error);
    }
    return vec3(0.0);
}

#endif
