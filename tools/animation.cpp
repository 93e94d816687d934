// SPDX-License-Identifier: MIT
// Animation frames and their video (ffmpeg as a subprocess).
#include "tools/animation.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "core/system/subprocess.h"
#include "core/system/temp_file.h"
#include "tools/cli_common.h"

namespace rt::cli {

namespace fs = std::filesystem;

namespace {

/// Digits of a frame number: 4, more when the last frame needs them.
int frameDigits(int n) {
    int digits = 1;
    for (int last = std::max(n - 1, 0); last >= 10; last /= 10) ++digits;
    return std::max(digits, 4);
}

std::string lowerExtension(const std::string &path) {
    std::string ext = fs::path(path).extension().string();
    for (auto &ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    return ext;
}

/// Shortest text that reads back as the same double: $t as the scene sees it.
std::string exactText(double v) {
    char buf[32];
    auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

/// <output folder>/<output stem>.mp4 unless --video names the file.
std::string videoFile(const AnimationArgs &a, const std::string &output) {
    if (!a.video.empty()) return a.video;
    return fs::path(output).replace_extension(".mp4").string();
}

/// Usage errors (exit 2) found before any frame is rendered.
void checkUsage(const AnimationArgs &a, const std::string &scene, const std::string &output) {
    if (output.empty())
        throw std::invalid_argument(
            "--encode-only needs -o, the image name the frames derive from "
            "(name.png for name_0000.png ...)");
    if (!a.encodeOnly && lowerExtension(scene) != ".scad")
        throw std::invalid_argument("--frames animates a .scad scene through $t; '" + scene +
                                    "' is a static scene (glTF animations are not read)");
    if (a.frame >= a.frames)
        throw std::invalid_argument("--frame " + std::to_string(a.frame) + " is not a frame of " +
                                    std::to_string(a.frames) + " (0 to " +
                                    std::to_string(a.frames - 1) + ")");
    std::string ext = lowerExtension(output);
    if (ext != ".png" && ext != ".exr")
        throw std::invalid_argument("-o: frames are written as .png or .exr, not '" + output + "'");
    requireOutputFile(output, "-o");
    if (a.frame < 0) {
        std::string video = videoFile(a, output);
        std::string vext = lowerExtension(video);
        if (vext != ".mp4" && vext != ".gif")
            throw std::invalid_argument("--video: '" + video + "' is neither .mp4 nor .gif");
        requireOutputFile(video, "--video");
    }
}

}  // namespace

void AnimationArgs::addTo(CLI::App &cmd) {
    auto *framesOpt = addNumber(cmd, "--frames", frames,
                                "Animate a .scad scene: render N frames with $t = i/N (i = 0..N-1, "
                                "as openscad --animate N) to <name>_0000.png ..., then a video "
                                "with ffmpeg (see --video)",
                                1, kMaxFrames);
    // ffmpeg's MP4 muxer refuses rates below about 1e-4; 0.001 is a frame every 1000 s
    addNumber(cmd, "--fps", fps, "--frames: frames per second of the video", kMinFps, kMaxFps)
        ->needs(framesOpt);
    auto *frameOpt = addNumber(cmd, "--frame", frame,
                               "--frames: render only frame I (0..N-1; a share of a job array), "
                               "no video",
                               0, kMaxFrames - 1);
    frameOpt->needs(framesOpt);
    auto *videoOpt = cmd.add_option("--video", video,
                                    "--frames: the video file, .mp4 (H.264) or .gif. Default: "
                                    "<name>.mp4 beside the frames");
    videoOpt->needs(framesOpt)->excludes(frameOpt);
    cmd.add_flag("--encode-only", encodeOnly,
                 "--frames: encode the frames already rendered into the video without "
                 "rendering (the scene may be left out; -o names the frames)")
        ->needs(framesOpt)
        ->excludes(frameOpt);
}

double frameTime(int i, int n) { return i * (1.0 / n); }

std::string frameFileName(const std::string &output, int i, int n) {
    fs::path p(output);
    char num[32];
    std::snprintf(num, sizeof num, "_%0*d", frameDigits(n), i);
    std::string name = p.stem().string() + num + p.extension().string();
    return p.has_parent_path() ? (p.parent_path() / name).string() : name;
}

std::string framePattern(const std::string &output, int n) {
    auto literal = [](const std::string &text) {
        std::string out;
        for (char ch : text) out += ch == '%' ? std::string("%%") : std::string(1, ch);
        return out;
    };
    fs::path p(output);
    std::string folder = p.has_parent_path() ? p.parent_path().string() + "/" : "";
    return "file:" + literal(folder + p.stem().string()) + "_%0" + std::to_string(frameDigits(n)) +
           "d" + literal(p.extension().string());
}

void encodeVideo(const std::string &output, int n, double fps, const std::string &video) {
    // Every frame must be there: ffmpeg would stop quietly at the first gap
    for (int i = 0; i < n; ++i) {
        std::string f = frameFileName(output, i, n);
        std::error_code ec;
        if (!fs::is_regular_file(f, ec))
            throw std::runtime_error("cannot encode " + video + ": frame " + std::to_string(i) +
                                     " of " + std::to_string(n) + " (" + f + ") is missing");
    }
    if (!programOnPath("ffmpeg"))
        throw std::runtime_error("cannot encode " + video +
                                 ": ffmpeg is not installed (scripts/setup.sh installs it)");

    // Written beside the target under a temporary name and renamed when ffmpeg succeeds
    std::string vext = lowerExtension(video);
    TempFile partial(video, vext);
    TempFile log(video, ".log");
    char rate[32];
    std::snprintf(rate, sizeof rate, "%.10g", fps);
    std::vector<std::string> args = {"ffmpeg", "-nostdin", "-hide_banner", "-y"};
    // EXR frames hold linear values: shown through the sRGB curve, as a PNG frame is
    if (lowerExtension(output) == ".exr") args.insert(args.end(), {"-apply_trc", "iec61966_2_1"});
    args.insert(args.end(),
                {"-f", "image2", "-pattern_type", "sequence", "-framerate", rate, "-start_number",
                 "0", "-i", framePattern(output, n), "-frames:v", std::to_string(n)});
    if (vext == ".gif") {
        // One palette made from all frames, looping forever
        args.insert(args.end(),
                    {"-vf", "split[a][b];[a]palettegen[p];[b][p]paletteuse", "-loop", "0"});
    } else {
        // yuv420p (what players expect) halves the colour resolution, so H.264 needs an even
        // width and height: an odd one gets a black line
        args.insert(args.end(), {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264",
                                 "-pix_fmt", "yuv420p", "-movflags", "+faststart"});
    }
    // "file:" makes it a file name whatever it looks like (an option, another protocol)
    args.push_back("file:" + partial.path());
    ProcessOptions po;
    po.logFile = log.path();
    po.timeoutSeconds = kMaxTimeoutSeconds;
    ProcessResult pr = runProcess(args, po);
    if (pr.exitCode != 0)
        throw std::runtime_error("ffmpeg failed to encode " + video + " (exit " +
                                 std::to_string(pr.exitCode) + "); its last lines:\n" +
                                 lastLines(pr.log, 12));
    partial.commit();
}

int runAnimation(const AnimationArgs &a, const std::string &scene, const std::string &output,
                 bool quiet,
                 const std::function<void(double time, const std::string &path)> &renderFrame) {
    using clock = std::chrono::steady_clock;
    checkUsage(a, scene, output);
    std::string video = videoFile(a, output);
    if (!a.encodeOnly) {
        // Each frame evaluates the scene afresh: nothing of one frame is kept for the next
        int first = a.frame >= 0 ? a.frame : 0, last = a.frame >= 0 ? a.frame : a.frames - 1;
        auto t0 = clock::now();
        for (int i = first; i <= last; ++i) {
            std::string path = frameFileName(output, i, a.frames);
            double t = frameTime(i, a.frames);
            try {
                renderFrame(t, path);
            } catch (...) {
                std::fprintf(stderr, "scadray: error in frame %d of %d ($t = %s, %s):\n", i,
                             a.frames, exactText(t).c_str(), path.c_str());
                throw;
            }
        }
        double seconds = std::chrono::duration<double>(clock::now() - t0).count();
        int count = last - first + 1;
        if (!quiet && count > 1)
            std::fprintf(stderr, "scadray: %d frames in %.3f s (%.2f frames/s)\n", count, seconds,
                         count / std::max(seconds, 1e-9));
        if (a.frame >= 0) return kExitOk;
        if (!programOnPath("ffmpeg")) {
            std::fprintf(stderr,
                         "scadray: warning: ffmpeg is not installed: %d frames written, no video "
                         "%s (scripts/setup.sh installs ffmpeg)\n",
                         a.frames, video.c_str());
            return kExitOk;
        }
    }
    auto t0 = clock::now();
    encodeVideo(output, a.frames, a.fps, video);
    if (!quiet)
        std::fprintf(stderr, "scadray: %s: %d frames at %s fps, %.3f s\n", video.c_str(), a.frames,
                     exactText(a.fps).c_str(),
                     std::chrono::duration<double>(clock::now() - t0).count());
    return kExitOk;
}

}  // namespace rt::cli
