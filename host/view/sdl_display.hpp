#pragma once
// The viewer's window: an SDL2 window whose renderer scales the latest picture (uploaded to a
// streaming texture) to the window, with the help panel (view/help_panel.hpp) drawn over it in
// the window's own pixels. The image keeps the
// scene's size and aspect ratio; a resized window scales it, with black bars if needed.
#include <cstdint>
#include <string>

#include "image/image.hpp"

struct SDL_Window;
struct SDL_Renderer;
struct SDL_Texture;

namespace lancer::view {

class SdlDisplay {
public:
    // Opens a window of the image size. Throws UserError when there is no display.
    SdlDisplay(const std::string& title, int width, int height);
    ~SdlDisplay();
    SdlDisplay(const SdlDisplay&) = delete;
    SdlDisplay& operator=(const SdlDisplay&) = delete;

    // The scene's image size changed (a reloaded scene): the window follows.
    void set_image_size(int width, int height);
    // Uploads `image` (any size: previews are smaller, and scaled up smoothly).
    void show(const Rgb8Image& image);
    void toggle_help() { help_visible_ = !help_visible_; }
    // Draws the picture and the help if shown; read_pixels() then returns what the window
    // shows until present() puts it on screen.
    void draw();
    Rgb8Image read_pixels();
    void present();
    void set_title(const std::string& title);

    std::uint32_t window_id() const;
    std::string renderer_name() const;
    double last_upload_ms() const { return upload_ms_; }

private:
    void draw_help();

    SDL_Window* window_ = nullptr;
    SDL_Renderer* renderer_ = nullptr;
    SDL_Texture* picture_ = nullptr;
    SDL_Texture* help_ = nullptr;
    int width_, height_;            // the scene's image size: the renderer's logical size
    int picture_w_ = 0, picture_h_ = 0;
    int help_for_w_ = 0, help_for_h_ = 0;  // the window size help_ was made for
    int help_x_ = 0, help_y_ = 0, help_w_ = 0, help_h_ = 0;  // where it goes, in window pixels
    bool help_visible_ = false;
    double upload_ms_ = 0.0;
};

}  // namespace lancer::view
