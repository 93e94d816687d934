// SPDX-License-Identifier: MIT
// `scadray render --frames N`: the frames of a .scad animation ($t = i/N), their file names,
// and the video ffmpeg encodes from them.
#pragma once

#include <functional>
#include <string>

namespace CLI {
class App;
}

namespace rt::cli {

/// Frames per second of the video unless --fps says otherwise, and --fps's range (ffmpeg's MP4
/// muxer refuses rates below about 1e-4, so a slower one would fail only after every frame).
constexpr double kDefaultFps = 25;
constexpr double kMinFps = 0.001;
constexpr double kMaxFps = 1000;
/// Most frames of one animation (11 hours at 25 fps).
constexpr int kMaxFrames = 1'000'000;

/// The animation options of `render`.
struct AnimationArgs {
    int frames = 0;  ///< --frames N; 0 = one still picture
    double fps = kDefaultFps;
    int frame = -1;     ///< --frame I: only this frame (a job array's share); -1 = all
    std::string video;  ///< --video; empty = <output stem>.mp4
    bool encodeOnly = false;

    /// Registers --frames, --fps, --frame, --video and --encode-only; the options that only
    /// make sense with --frames need it (a usage error otherwise).
    void addTo(CLI::App &cmd);
    bool active() const { return frames > 0; }
};

/// `$t` of frame i of n, bit for bit as `openscad --animate n` sets it: i * (1.0 / n).
double frameTime(int i, int n);

/// name_0007.png for output "name.png", frame 7: the frame number with 4 digits, more when
/// n - 1 needs them, before the output's extension.
std::string frameFileName(const std::string &output, int i, int n);

/// The frames' names as ffmpeg's image2 pattern ("file:" + the name with every '%' of the
/// output's folder and stem doubled and the frame number as %0Nd), so that no name can be an
/// option, another protocol, or a pattern of its own.
std::string framePattern(const std::string &output, int n);

/// Runs an animation: renders each frame (or only args.frame) through `renderFrame(time,
/// path)`, then, for a full run, encodes the video when ffmpeg is installed (one warning
/// naming ffmpeg when not). With args.encodeOnly only encodes the frames already there.
/// `scene` is the scene file (a .scad; other types are a usage error), empty with
/// --encode-only; `output` the image name the frame names derive from. A failing frame ends
/// the run with a line naming it, its exception passed on.
int runAnimation(const AnimationArgs &args, const std::string &scene, const std::string &output,
                 bool quiet,
                 const std::function<void(double time, const std::string &path)> &renderFrame);

/// Encodes frames 0..n-1 of `output` (frameFileName) into `video` (.mp4: H.264, yuv420p, an odd
/// width or height padded by one black line; .gif: a palette made for the frames) at `fps`.
/// Throws std::runtime_error naming the first missing frame, a missing ffmpeg, or ffmpeg's
/// failure with its last lines. The video is written atomically.
void encodeVideo(const std::string &output, int n, double fps, const std::string &video);

}  // namespace rt::cli
