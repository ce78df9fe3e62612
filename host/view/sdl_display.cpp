#include "view/sdl_display.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>

#include <SDL.h>

#include "core/error.hpp"
#include "view/help_panel.hpp"

namespace lancer::view {
namespace {

std::string sdl_error(const std::string& what) { return what + ": " + SDL_GetError(); }

}  // namespace

SdlDisplay::SdlDisplay(const std::string& title, int width, int height) : width_(width), height_(height) {
    // lancer handles SIGINT and SIGTERM itself (a signalfd in the file watcher); SDL's handlers
    // would race with it.
    SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
    // Without a display SDL would fall back to its offscreen driver: a window nobody sees, and
    // a viewer that runs forever. Say so instead (SDL_VIDEODRIVER still chooses explicitly).
    auto set = [](const char* name) { return std::getenv(name) && *std::getenv(name); };
    const bool driver_chosen = set("SDL_VIDEODRIVER");
    if (!driver_chosen && !set("DISPLAY") && !set("WAYLAND_DISPLAY"))
        throw UserError("cannot open a window: no display (neither DISPLAY nor WAYLAND_DISPLAY is set)");
    // Only the display that is there: probing others (Wayland without a compositor) prints its
    // own complaints, and SDL's last resort is an invisible window.
    if (!driver_chosen) SDL_SetHint(SDL_HINT_VIDEODRIVER, set("WAYLAND_DISPLAY") ? "wayland,x11" : "x11");
    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
        auto value = [&](const char* name) { return set(name) ? std::string(std::getenv(name)) : std::string(); };
        std::string where = driver_chosen ? "with SDL_VIDEODRIVER=" + value("SDL_VIDEODRIVER")
                                          : "on display '" + (set("DISPLAY") ? value("DISPLAY") : value("WAYLAND_DISPLAY")) + "'";
        std::string message = sdl_error("cannot open a window " + where);
        SDL_Quit();  // what a failed SDL_Init did start (its D-Bus connection) is closed too
        throw UserError(message);
    }
    // A picture larger than the screen gets a window that fits, showing it scaled down.
    int window_w = width, window_h = height;
    SDL_Rect usable;
    if (SDL_GetDisplayUsableBounds(0, &usable) == 0 && usable.w > 0 && usable.h > 0) {
        double fit = std::min({1.0, double(usable.w) / width, double(usable.h) / height});
        window_w = std::max(1, int(width * fit));
        window_h = std::max(1, int(height * fit));
    }
    window_ = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED, window_w, window_h,
                               SDL_WINDOW_RESIZABLE);
    if (!window_) {
        std::string message = sdl_error("cannot open a window");
        SDL_Quit();
        throw UserError(message);
    }
    renderer_ = SDL_CreateRenderer(window_, -1, 0);
    if (!renderer_) {
        std::string message = sdl_error("cannot draw in the window (SDL_CreateRenderer)");
        SDL_DestroyWindow(window_);
        SDL_Quit();
        throw UserError(message);
    }
    SDL_RendererInfo info{};
    SDL_GetRendererInfo(renderer_, &info);
    if ((info.max_texture_width && width > info.max_texture_width) ||
        (info.max_texture_height && height > info.max_texture_height)) {
        std::string message = "the picture is " + std::to_string(width) + "x" + std::to_string(height) +
                              ", larger than the window can show (" + std::to_string(info.max_texture_width) + "x" +
                              std::to_string(info.max_texture_height) + "); view it smaller with --width and --height";
        SDL_DestroyRenderer(renderer_);
        SDL_DestroyWindow(window_);
        SDL_Quit();
        throw UserError(message);
    }
    SDL_RenderSetLogicalSize(renderer_, width, height);
}

SdlDisplay::~SdlDisplay() {
    if (help_) SDL_DestroyTexture(help_);
    if (picture_) SDL_DestroyTexture(picture_);
    SDL_DestroyRenderer(renderer_);
    SDL_DestroyWindow(window_);
    SDL_Quit();
}

void SdlDisplay::set_image_size(int width, int height) {
    if (width == width_ && height == height_) return;
    width_ = width;
    height_ = height;
    SDL_SetWindowSize(window_, width, height);
    SDL_RenderSetLogicalSize(renderer_, width, height);
}

void SdlDisplay::show(const Rgb8Image& image) {
    auto start = std::chrono::steady_clock::now();
    if (!picture_ || picture_w_ != image.width || picture_h_ != image.height) {
        if (picture_) SDL_DestroyTexture(picture_);
        picture_ = SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_RGB24, SDL_TEXTUREACCESS_STREAMING, image.width,
                                     image.height);
        if (!picture_) throw std::runtime_error(sdl_error("SDL_CreateTexture"));
        picture_w_ = image.width;
        picture_h_ = image.height;
    }
    SDL_UpdateTexture(picture_, nullptr, image.bytes.data(), image.width * 3);
    upload_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void SdlDisplay::draw_help() {
    int out_w = 0, out_h = 0;
    SDL_GetRendererOutputSize(renderer_, &out_w, &out_h);
    if (help_for_w_ != out_w || help_for_h_ != out_h) {
        if (help_) SDL_DestroyTexture(help_);
        help_ = nullptr;
        help_for_w_ = out_w;
        help_for_h_ = out_h;
        HelpPanel panel = help_panel(out_w, out_h);
        help_x_ = panel.x;
        help_y_ = panel.y;
        help_w_ = panel.canvas.width;
        help_h_ = panel.canvas.height;
        if (help_w_ == 0) return;  // not even the note fits
        help_ = SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_ABGR8888, SDL_TEXTUREACCESS_STATIC, help_w_, help_h_);
        if (!help_) throw std::runtime_error(sdl_error("SDL_CreateTexture"));
        SDL_UpdateTexture(help_, nullptr, panel.canvas.rgba.data(), help_w_ * 4);
        SDL_SetTextureBlendMode(help_, SDL_BLENDMODE_BLEND);
    }
    if (!help_) return;
    // In window pixels, not the picture's: readable however the picture is scaled.
    SDL_RenderSetLogicalSize(renderer_, 0, 0);
    SDL_Rect where{help_x_, help_y_, help_w_, help_h_};
    SDL_RenderCopy(renderer_, help_, nullptr, &where);
    SDL_RenderSetLogicalSize(renderer_, width_, height_);
}

void SdlDisplay::draw() {
    SDL_SetRenderDrawColor(renderer_, 0, 0, 0, 255);
    SDL_RenderClear(renderer_);
    if (picture_) {
        // Scaled pictures (previews, a resized window, one larger than the screen) are drawn
        // smoothly; one shown 1:1 keeps its exact pixels.
        int out_w = 0, out_h = 0;
        SDL_GetRendererOutputSize(renderer_, &out_w, &out_h);
        bool one_to_one = picture_w_ == out_w && picture_h_ == out_h;
        SDL_SetTextureScaleMode(picture_, one_to_one ? SDL_ScaleModeNearest : SDL_ScaleModeLinear);
        SDL_RenderCopy(renderer_, picture_, nullptr, nullptr);
    }
    if (help_visible_) draw_help();
}

Rgb8Image SdlDisplay::read_pixels() {
    int w = 0, h = 0;
    SDL_GetRendererOutputSize(renderer_, &w, &h);
    Rgb8Image image{w, h, std::vector<std::uint8_t>(std::size_t(w) * h * 3)};
    if (SDL_RenderReadPixels(renderer_, nullptr, SDL_PIXELFORMAT_RGB24, image.bytes.data(), w * 3) != 0)
        throw std::runtime_error(sdl_error("SDL_RenderReadPixels"));
    return image;
}

void SdlDisplay::present() { SDL_RenderPresent(renderer_); }

void SdlDisplay::set_title(const std::string& title) { SDL_SetWindowTitle(window_, title.c_str()); }

std::uint32_t SdlDisplay::window_id() const { return SDL_GetWindowID(window_); }

std::string SdlDisplay::renderer_name() const {
    SDL_RendererInfo info{};
    SDL_GetRendererInfo(renderer_, &info);
    return info.name ? info.name : "unknown";
}

}  // namespace lancer::view
