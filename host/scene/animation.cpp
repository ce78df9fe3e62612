#include "scene/animation.hpp"

#include <cmath>
#include <stdexcept>

#include <glm/common.hpp>

#include "scene/placement.hpp"
#include "scene/shape_bounds.hpp"

namespace lancer {

dvec3 Orbit::position_at(double time) const {
    double angle = (start_angle_deg + 360.0 * turns * time) * (M_PI / 180.0);
    return center + dvec3(std::cos(angle) * radius, height, std::sin(angle) * radius);
}

double frame_time(const Animation& animation, int frame) {
    if (animation.cyclic) return double(frame) / double(animation.frames);
    if (animation.frames < 2) return 0.0;
    return double(frame) / double(animation.frames - 1);
}

void translate(Shape& shape, const dvec3& offset) {
    struct Mover {
        const dvec3& d;
        void operator()(Sphere& s) const { s.center += d; }
        void operator()(Plane& p) const { p.point += d; }
        void operator()(Rectangle& r) const { r.corner += d; }
        void operator()(Disc& c) const { c.center += d; }
        void operator()(Cone& c) const {
            c.base += d;
            c.cap += d;
        }
        void operator()(Torus& o) const { o.center += d; }
        void operator()(Blob& o) const {
            for (BlobComponent& k : o.components) {
                k.a += d;
                k.b += d;
            }
            prepare_blob(o);
        }
        void operator()(Mesh&) const {  // moved by its placement (place() always gives it one)
            throw std::logic_error("a mesh is moved by its placement, not by its shape");
        }
        void operator()(SphereSet&) const { throw std::logic_error("a sphere set is moved by its placement, not by its shape"); }
        void operator()(Sor&) const { throw std::logic_error("a sor is moved by its placement, not by its shape"); }
        void operator()(Prism&) const { throw std::logic_error("a prism is moved by its placement, not by its shape"); }
        void operator()(Lathe&) const { throw std::logic_error("a lathe is moved by its placement, not by its shape"); }
        void operator()(Superellipsoid&) const {
            throw std::logic_error("a superellipsoid is moved by its placement, not by its shape");
        }
        void operator()(Csg& c) const {
            for (Object& leaf : c.leaves) translate(leaf, d);
            c.lo += d;
            c.hi += d;
        }
        void operator()(Box& b) const {
            b.min += d;
            b.max += d;
        }
        void operator()(ParametricObject& p) const {
            p.surface->to_world[3] += glm::dvec4(d, 0.0);  // translation column of the affine map
            p.bounds_lo += d;
            p.bounds_hi += d;
        }
        void operator()(ImplicitObject& o) const {
            glm::dmat4 m = o.surface->to_world;
            m[3] += glm::dvec4(d, 0.0);
            o.surface->place(m);
        }
        void operator()(BezierSurface& b) const {
            for (auto& patch : b.patches)
                for (auto& p : patch.points) p += d;
        }
    };
    std::visit(Mover{offset}, shape);
}

Scene scene_at(const Scene& scene, double time) {
    Scene s = scene;
    s.animation.reset();
    if (!scene.animation) return s;
    const Animation& a = *scene.animation;
    // Time 1 of a cyclic animation is time 0 exactly, not a full turn that rounds to nearly it.
    if (a.cyclic) time -= std::floor(time);

    if (a.camera_orbit) {
        // Only eye and look_at move; the basis (right, true up) is rebuilt from them and the
        // world's up for each frame, which is what the original project failed to do.
        s.camera.eye = a.camera_orbit->position_at(time);
        s.camera.look_at = a.camera_orbit->center;
    }
    // A light moves by its position (an area light's centre: the rectangle moves as a whole). A
    // spot given point_at keeps aiming at that point; one given a direction keeps its direction.
    for (const LightOrbit& o : a.light_orbits) s.lights[o.light].position = o.orbit.position_at(time);
    for (const LightKeys& k : a.light_keys) {
        Light& light = s.lights[k.light];
        if (k.position) light.position = sample(*k.position, time, a.cyclic);
        if (k.color) light.color = glm::max(sample(*k.color, time, a.cyclic), dvec3(0.0));
    }
    for (Light& light : s.lights) aim_spot(light);
    for (const ObjectKeys& k : a.object_keys) {
        const dvec3 offset = sample(k.translate, time, a.cyclic);
        for (std::size_t i = k.object; i < k.object + k.count; ++i) translate(s.objects[i], offset);
    }
    return s;
}

}  // namespace lancer
