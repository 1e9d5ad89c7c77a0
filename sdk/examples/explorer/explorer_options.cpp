#include "explorer_options.hpp"

#include <charconv>
#include <stdexcept>

namespace explorer {
namespace {

// The value after option `name`, or an error saying it is missing.
std::string valueOf(int& i, int argc, char** argv) {
  const std::string name = argv[i];
  if (i + 1 >= argc) throw std::invalid_argument(name + " needs a value");
  return argv[++i];
}

template <typename Number>
Number numberOf(const std::string& name, const std::string& text) {
  Number value{};
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size())
    throw std::invalid_argument(name + " takes a number, not '" + text + "'");
  return value;
}

// "1280x720" into width and height, each at least 64 pixels (room for the panel).
void readSize(const std::string& text, ExplorerOptions& options) {
  const std::size_t x = text.find('x');
  if (x == std::string::npos) throw std::invalid_argument("--size takes WIDTHxHEIGHT, e.g. 1280x720");
  options.width = numberOf<int>("--size", text.substr(0, x));
  options.height = numberOf<int>("--size", text.substr(x + 1));
  if (options.width < 64 || options.height < 64) throw std::invalid_argument("--size must be at least 64x64");
}

}  // namespace

std::string usage() {
  return "usage: mars-explorer [PIPELINE.yaml] [--size WxH] [--hide LAYER]... [--date YYYY-MM-DD]\n"
         "                     [--altitude METRES] [--screenshot FILE.png [--frames N]]\n";
}

ExplorerOptions parseOptions(int argc, char** argv) {
  ExplorerOptions options;
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument == "--size")
      readSize(valueOf(i, argc, argv), options);
    else if (argument == "--hide")
      options.hidden.push_back(valueOf(i, argc, argv));
    else if (argument == "--date")
      options.date = valueOf(i, argc, argv);
    else if (argument == "--altitude")
      options.altitude = numberOf<double>(argument, valueOf(i, argc, argv));
    else if (argument == "--screenshot")
      options.screenshot = valueOf(i, argc, argv);
    else if (argument == "--frames")
      options.frames = numberOf<int>(argument, valueOf(i, argc, argv));
    else if (argument.starts_with("-"))
      throw std::invalid_argument("unknown option " + argument);
    else if (options.pipeline.empty())
      options.pipeline = argument;
    else
      throw std::invalid_argument("one pipeline only, not also " + argument);
  }
  if (options.frames < 1) throw std::invalid_argument("--frames must be at least 1");
  return options;
}

}  // namespace explorer
