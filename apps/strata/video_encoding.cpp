#include "video_encoding.hpp"

#include <spawn.h>
#include <sys/wait.h>

#include <cstdlib>
#include <cstring>
#include <vector>

#include <strata/error.hpp>

#include "interrupt_cleanup.hpp"

extern char** environ;

namespace strata::cli {
namespace {

std::filesystem::path findOnPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::string directories = path ? path : "";
  for (std::size_t begin = 0; begin <= directories.size();) {
    const std::size_t end = std::min(directories.find(':', begin), directories.size());
    const std::filesystem::path candidate = std::filesystem::path(directories.substr(begin, end - begin)) / program;
    std::error_code error;
    if (end > begin && std::filesystem::is_regular_file(candidate, error)) return candidate;
    begin = end + 1;
  }
  return {};
}

// Runs a program with its arguments, without a shell (no quoting of file names), and returns its exit code.
int runProgram(const std::vector<std::string>& arguments) {
  std::vector<char*> argv;
  for (const auto& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  unblockSignalsInChild(attributes);
  pid_t child = 0;
  const int started = posix_spawn(&child, argv[0], nullptr, &attributes, argv.data(), environ);
  posix_spawnattr_destroy(&attributes);
  if (started != 0) return -1;
  int status = 0;
  if (waitpid(child, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace

bool isVideoFile(const std::filesystem::path& output) {
  const std::string extension = output.extension().string();
  return extension == ".mp4" || extension == ".webm";
}

std::string videoFramePattern(const std::filesystem::path& folder) { return (folder / "frame_%05d.png").string(); }

std::filesystem::path requireFfmpeg() {
  const std::filesystem::path ffmpeg = findOnPath("ffmpeg");
  if (ffmpeg.empty())
    throw Error(SourceLocation{"-o"}, "a video needs ffmpeg, and there is none on PATH",
                "install it (Debian: sudo apt-get install ffmpeg), or give -o a frame pattern such as "
                "out/frame_%05d.png and encode the frames yourself");
  return ffmpeg;
}

void encodeVideo(const std::filesystem::path& ffmpeg, const std::string& pattern, double framesPerSecond,
                 const std::filesystem::path& video) {
  // yuv420p: the chroma format every player decodes, which halves the chroma's resolution, so an odd width or
  // height is padded by a pixel; -y: `video` is in a fresh scratch folder, where nothing of the user's is.
  const int status =
      runProgram({ffmpeg.string(), "-y", "-loglevel", "error", "-framerate", std::to_string(framesPerSecond), "-i",
                  pattern, "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p", video.string()});
  if (status != 0)
    throw Error(
        SourceLocation{"-o"},
        "ffmpeg could not encode " + video.string() + " (exit status " + std::to_string(status) + ")",
        "read ffmpeg's message above; the frames are kept in " + std::filesystem::path(pattern).parent_path().string());
}

}  // namespace strata::cli
