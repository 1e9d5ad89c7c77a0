#pragma once
#include <filesystem>
#include <string>

namespace strata::cli {

// `strata render --path ... -o out/flyin.mp4`: the frames are written as PNGs and then encoded by ffmpeg,
// when it is installed; Strata links no video codec of its own.

// Whether `-o` names a video (.mp4 or .webm) rather than a frame pattern.
bool isVideoFile(const std::filesystem::path& output);
// The frames of a video in `folder` (a scratch folder beside it): folder/frame_%05d.png.
std::string videoFramePattern(const std::filesystem::path& folder);
// The ffmpeg on PATH; throws strata::Error naming -o with how to install it when there is none (checked
// before rendering, so a missing encoder costs no frames).
std::filesystem::path requireFfmpeg();
// Encodes the numbered frames of `pattern` (frame_%05d.png from 0) at `framesPerSecond` into `video`; throws
// strata::Error when ffmpeg fails.
void encodeVideo(const std::filesystem::path& ffmpeg, const std::string& pattern, double framesPerSecond,
                 const std::filesystem::path& video);

}  // namespace strata::cli
