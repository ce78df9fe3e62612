#pragma once
#include "render/renderer.hpp"

namespace lancer {

// The reference renderer: double precision, every core, rows handed out dynamically.
class CpuRenderer final : public Renderer {
public:
    explicit CpuRenderer(unsigned threads = 0);  // 0: one per hardware thread
    std::string description() const override;
    FloatImage render(const Scene& scene, const ProgressFn& progress) override;
    FloatImage render_hits(const Scene& scene) override;

private:
    unsigned threads_;
};

}  // namespace lancer
