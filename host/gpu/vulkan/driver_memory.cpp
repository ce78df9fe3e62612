#include "gpu/vulkan/driver_memory.hpp"

#include <algorithm>
#include <cstdlib>
#include <string>
#include <variant>

#include <unistd.h>

#include "core/process_limits.hpp"
#include "surface/expr/program.hpp"

namespace lancer::gpu {
namespace {

constexpr std::uint64_t kMiB = 1 << 20;

// lavapipe runs LP_NUM_THREADS threads (default: the CPUs, at most 16); each has a stack and
// buffers of its own.
std::uint64_t driver_threads() {
    if (const char* env = std::getenv("LP_NUM_THREADS")) return std::clamp<long>(std::atol(env), 0, 16);
    return std::clamp<long>(::sysconf(_SC_NPROCESSORS_ONLN), 1, 16);
}

const std::string kAdvice = "or render with --backend cpu";

}  // namespace

void check_driver_startup_memory() {
    // Measured (docs/robustness.md): a trivial scene's peak address space on lavapipe is
    // 337 MiB + 16 MiB per thread with one malloc arena (adapt_to_address_space_limit), of
    // which ~40 MiB are lancer's before the driver is loaded; its peak resident memory 145 MiB.
    const std::uint64_t address_space = (320 + 16 * driver_threads()) * kMiB;
    check_memory_headroom(address_space, 140 * kMiB, "the Vulkan driver", kAdvice);
}

std::uint64_t compile_memory(const Scene& scene) {
    // The pipeline compile: with expression surfaces, glslang's run-time compile and a larger LLVM compile (the torus needs
    // 400 to 450 MiB of address space in all, against 386 for a scene without them), and about
    // 0.6 MiB more for every operation of a parametric surface (measured: 205 MiB peak resident
    // memory for a one-operation surface, 508 MiB for 511 operations).
    std::uint64_t operations = 0, implicit_operations = 0;
    bool expressions = false;
    for_each_object_and_leaf(scene.objects, [&](const Object& o) {
        if (const auto* p = std::get_if<ParametricObject>(&o.shape)) {
            expressions = true;
            const surface::Expr* xyz[] = {&p->surface->x, &p->surface->y, &p->surface->z};
            operations += static_cast<std::uint64_t>(surface::count_operations(surface::compile_program(xyz)));
        } else if (const auto* i = std::get_if<ImplicitObject>(&o.shape)) {
            // f becomes three float functions in the tracer (value and derivative along the ray,
            // gradient, interval enclosure), so each operation is counted three times; the
            // enclosure at a point in double, inlined at two places, is counted below.
            expressions = true;
            const auto n = static_cast<std::uint64_t>(surface::count_operations(i->surface->program));
            operations += 3 * n;
            implicit_operations += n;
        }
    });
    // The driver's compile of many implicit surfaces grows with the square of their operations
    // (docs/robustness.md, "Implicit surfaces' compile": 32 surfaces of 16 operations each peak
    // at 2.45 GiB of address space on Mesa 25 and 2.84 GiB on Mesa 22.3, 0.6 GiB over the linear
    // estimate); 5 KiB per operation squared covers both drivers' measured peaks by 10%. The
    // double enclosure adds 1.5 MiB per implicit operation (8 surfaces of 11 operations: 128
    // MiB more than without it, on both drivers).
    return (expressions ? 128 : 32) * kMiB + operations * (kMiB * 3 / 4) + implicit_operations * (kMiB * 3 / 2) +
           implicit_operations * implicit_operations * (kMiB * 5 / 1024);
}

RenderMemoryEstimate render_memory_estimate(const RenderSettings& render, std::uint64_t scene_buffer_bytes,
                                            std::uint64_t compile_bytes) {
    // The float image on the host and its copy while it is converted, the scene's buffers (host
    // visible memory on lavapipe: both host and device), and the pipeline compile.
    const std::uint64_t image = std::uint64_t(render.width) * std::uint64_t(render.height) * 16;
    return {2 * image + 2 * scene_buffer_bytes + compile_bytes, 2 * image + scene_buffer_bytes + compile_bytes};
}

RenderMemoryEstimate render_memory_estimate(const Scene& scene, std::uint64_t scene_buffer_bytes) {
    return render_memory_estimate(scene.render, scene_buffer_bytes, compile_memory(scene));
}

void check_render_memory(const RenderSettings& render, std::uint64_t scene_buffer_bytes, std::uint64_t compile_bytes) {
    const RenderMemoryEstimate need = render_memory_estimate(render, scene_buffer_bytes, compile_bytes);
    check_memory_headroom(need.address_space, need.resident, "this render", kAdvice);
}

}  // namespace lancer::gpu
