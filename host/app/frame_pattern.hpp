#pragma once
// Names of animation frames: an output path with one printf-style frame number field, `%d` or
// `%0Nd` (`%%` is a literal %), the same syntax ffmpeg's image sequence reader takes.
#include <optional>
#include <string>
#include <vector>

namespace lancer {

class FramePattern {
public:
    // The pattern in `text`, or nullopt when it has no frame field. Throws UserError for a
    // malformed one (`%s`, `%5d`, two fields, a field in the directory part).
    static std::optional<FramePattern> parse(const std::string& text);

    std::string path(int frame) const;
    const std::string& text() const { return text_; }
    std::string directory() const;  // "" when the frames go to the current directory

private:
    std::string text_;
    std::string prefix_, suffix_;  // with %% already turned into %
    int width_ = 0;                // 0: no padding
};

// True when `text` holds a well-formed frame field (%d, %0Nd): a still render refuses such a
// name rather than writing a file called orbit_%03d.png.
bool has_frame_field(const std::string& text);

// Digits of the last frame number (119 -> 3), so that frame names sort in order.
int frame_number_width(int frames);

// "%03d" for 120 frames, "%d" for up to 10.
std::string frame_field(int frames);

// NAME_%0Nd.png for the scene file NAME.toml, in the current directory.
std::string default_frame_pattern(const std::string& scene_path, int frames);

// Frames to render: "A-B" or "N", 0-based and inclusive, within an animation of `frames`.
struct FrameRange {
    int first = 0;
    int last = 0;
    bool single() const { return first == last; }
};
// Throws UserError naming the option and the valid range.
FrameRange parse_frame_range(const std::string& text, int frames);

// "0-4, 7, 9-11": a sorted list of frame numbers in short form.
std::string format_frame_list(const std::vector<int>& frames);

}  // namespace lancer
