#pragma once
// Frames -> video with ffmpeg (the Debian package "ffmpeg"), run with an argument vector, no shell.
// This replaces the original project's createvideo.sh.
#include <string>

namespace lancer {

// Before anything is rendered: `path` must end in .mp4, .webm or .gif and ffmpeg must be on
// PATH. Throws UserError otherwise.
void check_video_possible(const std::string& path);

// Encodes frames 0 to frames-1 of the printf-style `pattern` at `fps` into `output`: H.264
// (.mp4), VP9 (.webm) or a looping GIF with its own palette. Odd sizes are padded by one black
// row or column for the 4:2:0 codecs. ffmpeg writes a temporary file beside `output` which is
// renamed into place, so a failure leaves no partial video. Throws UserError with ffmpeg's
// message when it fails.
void make_video(const std::string& pattern, int frames, double fps, const std::string& output);

// The full path of `name` on PATH, or "" when it is not there.
std::string find_program(const std::string& name);

}  // namespace lancer
